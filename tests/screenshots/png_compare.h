// Comparing two RGBA images the way the golden tests do (README.md,
// "Screenshot tests"): a pixel fails when any channel differs by more than a
// tolerance; the images match when few enough pixels fail.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace gridcull {

struct RgbaImage {
    int width = 0, height = 0;
    std::vector<uint8_t> pixels;  // width * height * 4, rows from the top
};

// Reads a PNG as RGBA. False and `error` when it cannot.
bool readPng(const std::string& path, RgbaImage& image, std::string& error);
bool writePng(const std::string& path, const RgbaImage& image);

struct ImageDiff {
    bool same_size = false;
    int64_t failing_pixels = 0;
    int max_channel_difference = 0;
    RgbaImage diff;  // failing pixels red, others a dimmed grey of the expected image
};

// Every channel within `tolerance` (0..255) passes a pixel.
ImageDiff compareImages(const RgbaImage& actual, const RgbaImage& expected, int tolerance);

}  // namespace gridcull
