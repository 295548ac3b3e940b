#include "tests/screenshots/png_compare.h"

#include <algorithm>
#include <cstdlib>

#include <stb_image.h>
#include <stb_image_write.h>

namespace gridcull {

bool readPng(const std::string& path, RgbaImage& image, std::string& error) {
    int w = 0, h = 0, channels = 0;
    unsigned char* data = stbi_load(path.c_str(), &w, &h, &channels, 4);
    if (!data) {
        error = "cannot read '" + path + "': " + (stbi_failure_reason() ? stbi_failure_reason() : "?");
        return false;
    }
    image.width = w;
    image.height = h;
    image.pixels.assign(data, data + size_t(w) * size_t(h) * 4);
    stbi_image_free(data);
    return true;
}

bool writePng(const std::string& path, const RgbaImage& image) {
    return stbi_write_png(path.c_str(), image.width, image.height, 4, image.pixels.data(),
                          image.width * 4) != 0;
}

ImageDiff compareImages(const RgbaImage& actual, const RgbaImage& expected, int tolerance) {
    ImageDiff result;
    result.same_size = actual.width == expected.width && actual.height == expected.height;
    if (!result.same_size) return result;
    result.diff.width = expected.width;
    result.diff.height = expected.height;
    result.diff.pixels.resize(expected.pixels.size());
    for (size_t i = 0; i < expected.pixels.size(); i += 4) {
        int worst = 0;
        for (size_t c = 0; c < 4; ++c)
            worst = std::max(worst, std::abs(int(actual.pixels[i + c]) - int(expected.pixels[i + c])));
        result.max_channel_difference = std::max(result.max_channel_difference, worst);
        uint8_t* out = &result.diff.pixels[i];
        if (worst > tolerance) {
            ++result.failing_pixels;
            out[0] = 255, out[1] = 0, out[2] = 0;
        } else {
            const int grey = (expected.pixels[i] + expected.pixels[i + 1] + expected.pixels[i + 2]) / 6;
            out[0] = out[1] = out[2] = uint8_t(grey);
        }
        out[3] = 255;
    }
    return result;
}

}  // namespace gridcull
