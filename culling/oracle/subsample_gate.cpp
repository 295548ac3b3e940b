#include "culling/oracle/subsample_gate.h"

#include <algorithm>
#include <limits>

namespace gridcull {

void SubsampleGate::build(const IdDepthBuffer& buffer) {
    constexpr double kOpen = std::numeric_limits<double>::infinity();
    const int w = buffer.width(), h = buffer.height();
    const size_t pixels = size_t(w) * size_t(h);
    if (w != width_ || h != height_) {
        width_ = w;
        height_ = h;
        tiles_x_ = (w + kTile - 1) / kTile;
        gate_.assign(pixels, kOpen);
        row_max_.assign(pixels, kOpen);
        row_same_.assign(pixels, 0);
        tile_max_.assign(size_t(tiles_x_) * size_t((h + kTile - 1) / kTile), kOpen);
    }
    // Rows first: the nine-centre test is three row tests and one column test.
    for (int py = 0; py < h; ++py) {
        const double* depth = buffer.depthRow(py);
        const int32_t* id = buffer.indexRow(py);
        double* row_max = row_max_.data() + size_t(py) * size_t(w);
        uint8_t* row_same = row_same_.data() + size_t(py) * size_t(w);
        row_same[0] = 0;
        row_same[w - 1] = 0;
        for (int px = 1; px + 1 < w; ++px) {
            row_same[px] = id[px] >= 0 && id[px - 1] == id[px] && id[px + 1] == id[px];
            row_max[px] = std::max({depth[px - 1], depth[px], depth[px + 1]});
        }
    }
    std::fill(tile_max_.begin(), tile_max_.end(), 0.0);
    for (int py = 0; py < h; ++py) {
        double* gate = gate_.data() + size_t(py) * size_t(w);
        double* tiles = tile_max_.data() + size_t(py / kTile) * size_t(tiles_x_);
        if (py == 0 || py + 1 == h) {
            std::fill(gate, gate + w, kOpen);
            for (int tx = 0; tx < tiles_x_; ++tx) tiles[tx] = kOpen;
            continue;
        }
        const size_t above = size_t(py - 1) * size_t(w), here = above + size_t(w),
                     below = here + size_t(w);
        const int32_t* id_above = buffer.indexRow(py - 1);
        const int32_t* id = buffer.indexRow(py);
        const int32_t* id_below = buffer.indexRow(py + 1);
        for (int px = 0; px < w; ++px) {
            const bool covered = row_same_[above + size_t(px)] && row_same_[here + size_t(px)] &&
                                 row_same_[below + size_t(px)] && id_above[px] == id[px] &&
                                 id_below[px] == id[px];
            gate[px] = covered ? std::max({row_max_[above + size_t(px)], row_max_[here + size_t(px)],
                                           row_max_[below + size_t(px)]})
                               : kOpen;
            double& tile = tiles[px / kTile];
            tile = std::max(tile, gate[px]);
        }
    }
}

bool SubsampleGate::mayShow(const ScreenRange& cols, const ScreenRange& rows, double z) const {
    for (int ty = rows.lo / kTile; ty <= rows.hi / kTile; ++ty)
        for (int tx = cols.lo / kTile; tx <= cols.hi / kTile; ++tx)
            if (tile_max_[size_t(ty) * size_t(tiles_x_) + size_t(tx)] >= z) return true;
    return false;
}

}  // namespace gridcull
