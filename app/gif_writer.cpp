#include "app/gif_writer.h"

#include <cgif.h>

#include <algorithm>
#include <array>
#include <cstdio>

namespace gridcull {

namespace {

constexpr int kBins = 1 << 15;  // 5 bits per channel

int binOf(const uint8_t* p) {
    return (p[0] >> 3) << 10 | (p[1] >> 3) << 5 | (p[2] >> 3);
}

int writeChunk(void* context, const uint8_t* data, size_t bytes) {
    std::FILE* file = static_cast<std::FILE*>(context);
    return std::fwrite(data, 1, bytes, file) == bytes ? CGIF_OK : CGIF_EWRITE;
}

}  // namespace

void quantizeFrame(const std::vector<uint8_t>& rgba, std::vector<uint8_t>& palette,
                   std::vector<uint8_t>& indices) {
    const size_t pixels = rgba.size() / 4;
    // Per bin: how many pixels, and the sum of their colours (the bin's mean
    // becomes its palette colour, so a flat colour comes out exact).
    std::vector<uint32_t> count(kBins, 0);
    std::vector<std::array<uint64_t, 3>> sum(kBins, {0, 0, 0});
    for (size_t i = 0; i < pixels; ++i) {
        const uint8_t* p = &rgba[i * 4];
        const int bin = binOf(p);
        ++count[size_t(bin)];
        for (int c = 0; c < 3; ++c) sum[size_t(bin)][size_t(c)] += p[c];
    }
    std::vector<int> used;
    for (int bin = 0; bin < kBins; ++bin)
        if (count[size_t(bin)] > 0) used.push_back(bin);
    std::sort(used.begin(), used.end(),
              [&](int a, int b) { return count[size_t(a)] > count[size_t(b)]; });
    const size_t colours = std::min<size_t>(used.size(), 256);
    palette.assign(colours * 3, 0);
    for (size_t k = 0; k < colours; ++k) {
        const size_t bin = size_t(used[k]);
        for (int c = 0; c < 3; ++c)
            palette[k * 3 + size_t(c)] = uint8_t(sum[bin][size_t(c)] / count[bin]);
    }
    // Every used bin maps to its nearest palette colour.
    std::vector<uint8_t> nearest(kBins, 0);
    for (const int bin : used) {
        const int r = (bin >> 10 & 31) * 8 + 4, g = (bin >> 5 & 31) * 8 + 4, b = (bin & 31) * 8 + 4;
        int best = 0, best_distance = 1 << 30;
        for (size_t k = 0; k < colours; ++k) {
            const int dr = r - palette[k * 3], dg = g - palette[k * 3 + 1],
                      db = b - palette[k * 3 + 2];
            const int distance = dr * dr + dg * dg + db * db;
            if (distance < best_distance) {
                best_distance = distance;
                best = int(k);
            }
        }
        nearest[size_t(bin)] = uint8_t(best);
    }
    for (size_t k = 0; k < colours; ++k) nearest[size_t(used[k])] = uint8_t(k);
    indices.resize(pixels);
    for (size_t i = 0; i < pixels; ++i) indices[i] = nearest[size_t(binOf(&rgba[i * 4]))];
    if (palette.size() < 6) palette.resize(6, 0);  // GIF's smallest table holds two colours
}

struct GifWriter::Encoder {
    CGIF* gif = nullptr;
    std::vector<uint8_t> palette, indices;
    ~Encoder() {
        if (gif) cgif_close(gif);
    }
};

GifWriter::GifWriter() = default;
GifWriter::~GifWriter() = default;

bool GifWriter::open(const std::string& path, int width, int height, std::string& error) {
    if (width < 1 || height < 1 || width > 65535 || height > 65535) {
        error = "a GIF is 1 to 65535 pixels wide and high";
        return false;
    }
    if (!file_.open(path, error)) return false;
    path_ = path;
    width_ = width;
    height_ = height;
    encoder_ = std::make_unique<Encoder>();
    CGIF_Config config{};
    config.attrFlags = CGIF_ATTR_IS_ANIMATED | CGIF_ATTR_NO_GLOBAL_TABLE;
    config.width = uint16_t(width);
    config.height = uint16_t(height);
    config.numLoops = CGIF_INFINITE_LOOP;
    config.pWriteFn = writeChunk;
    config.pContext = file_.stream();
    encoder_->gif = cgif_newgif(&config);
    if (!encoder_->gif) {
        error = "cannot start a GIF in '" + path + "'";
        return false;
    }
    return true;
}

bool GifWriter::addFrame(const std::vector<uint8_t>& rgba, int delay_cs, std::string& error) {
    if (rgba.size() != size_t(width_) * size_t(height_) * 4) {
        error = "a GIF frame of the wrong size";
        return false;
    }
    quantizeFrame(rgba, encoder_->palette, encoder_->indices);
    CGIF_FrameConfig frame{};
    frame.attrFlags = CGIF_FRAME_ATTR_USE_LOCAL_TABLE;
    frame.pLocalPalette = encoder_->palette.data();
    frame.numLocalPaletteEntries = uint16_t(encoder_->palette.size() / 3);
    frame.pImageData = encoder_->indices.data();
    frame.delay = uint16_t(std::clamp(delay_cs, 2, 65535));
    if (cgif_addframe(encoder_->gif, &frame) != CGIF_OK) {
        error = "writing a frame to '" + path_ + "' failed";
        return false;
    }
    return true;
}

bool GifWriter::close(std::string& error) {
    const int result = cgif_close(encoder_->gif);
    encoder_->gif = nullptr;
    if (result != CGIF_OK) {
        error = "finishing '" + path_ + "' failed";
        return false;
    }
    return file_.commit(error);
}

}  // namespace gridcull
