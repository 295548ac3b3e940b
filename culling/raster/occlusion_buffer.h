// A software occlusion buffer, "an occlusion-buffer where a single bit per pixel
// shows if that pixel is free or occluded" (Hey, Tobler & Purgathofer, section
// 3). One bit per pixel, 64 pixels to a word, rows padded to whole words; a set
// bit is occluded.
//
// It is written from the shared rasterizer's z-buffer (culling/raster/
// id_depth_buffer.h) after each draw: a pixel is occluded once something
// was drawn at its centre. Queries count free pixels of a rectangle with word
// masks and popcounts, so a 32 x 32 cell costs 32 word reads (the POPCNT
// instruction where the CPU has it, chosen at run time, else a SWAR count).
#pragma once
#include <cstdint>
#include <vector>

#include "culling/raster/screen_mapping.h"

namespace gridcull {

class IdDepthBuffer;

class OcclusionBuffer {
public:
    // Allocates width x height bits (each >= 1); no-op when the size is unchanged.
    void resize(int width, int height);
    int width() const { return width_; }
    int height() const { return height_; }
    // Every pixel free. O(pixels / 64).
    void clear();
    // Marks occluded every pixel of `rect` whose depth in `zbuffer` is finite
    // (something was drawn there). zbuffer must have this buffer's size.
    void markDrawn(const IdDepthBuffer& zbuffer, const PixelRect& rect);
    // Marks every pixel of `rect` occluded (clipped to the image).
    void markOccluded(const PixelRect& rect);
    // Number of free pixels in `rect` (clipped to the image). O(rows * words).
    long long countFree(const PixelRect& rect) const;
    // The same count by the portable SWAR popcount alone (what countFree uses
    // on a CPU without POPCNT), so tests can compare both paths.
    long long countFreeSwar(const PixelRect& rect) const;
    bool occluded(int px, int py) const {
        return (bits_[size_t(py) * words_per_row_ + size_t(px >> 6)] >> (px & 63)) & 1u;
    }

private:
    int width_ = 0, height_ = 0;
    size_t words_per_row_ = 0;
    std::vector<uint64_t> bits_;
};

}  // namespace gridcull
