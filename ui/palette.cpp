#include "ui/palette.h"

namespace gridcull {

Rgb swatchColor(Swatch swatch) {
    switch (swatch) {
        case Swatch::Blue:
            return {0.00f, 0.45f, 0.70f};
        case Swatch::SkyBlue:
            return {0.34f, 0.71f, 0.91f};
        case Swatch::Vermillion:
            return {0.84f, 0.37f, 0.00f};
        case Swatch::Yellow:
            return {0.94f, 0.89f, 0.26f};
        case Swatch::Orange:
            return {0.90f, 0.62f, 0.00f};
        case Swatch::BluishGreen:
            return {0.00f, 0.62f, 0.45f};
        case Swatch::ReddishPurple:
            return {0.80f, 0.47f, 0.65f};
        case Swatch::NearBlack:
            return {0.03f, 0.03f, 0.04f};
        case Swatch::LightGrey:
            return {0.92f, 0.92f, 0.92f};
        case Swatch::Grey:
            return {0.62f, 0.62f, 0.64f};
        case Swatch::LineGrey:
            return {0.70f, 0.71f, 0.74f};
        case Swatch::DimGrey:
            return {0.36f, 0.36f, 0.38f};
        case Swatch::White:
        case Swatch::Count:
            break;
    }
    return {1.0f, 1.0f, 1.0f};
}

const char* swatchName(Swatch swatch) {
    switch (swatch) {
        case Swatch::Blue:
            return "blue";
        case Swatch::SkyBlue:
            return "sky blue";
        case Swatch::Vermillion:
            return "vermillion";
        case Swatch::Yellow:
            return "yellow";
        case Swatch::Orange:
            return "orange";
        case Swatch::BluishGreen:
            return "bluish green";
        case Swatch::ReddishPurple:
            return "reddish purple";
        case Swatch::NearBlack:
            return "near black";
        case Swatch::LightGrey:
            return "light grey";
        case Swatch::Grey:
            return "grey";
        case Swatch::LineGrey:
            return "line grey";
        case Swatch::DimGrey:
            return "dim grey";
        case Swatch::White:
            return "white";
        case Swatch::Count:
            break;
    }
    return "?";
}

Rgb viewBackgroundColor() {
    return {0.10f, 0.11f, 0.13f};
}

Rgb worldFillColor() {
    return {0.15f, 0.16f, 0.18f};
}

}  // namespace gridcull
