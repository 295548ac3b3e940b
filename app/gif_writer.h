// An animated GIF written frame by frame through Debian's libcgif (chosen over
// hand-written LZW: a packaged, fuzzed encoder; over an ffmpeg or ImageMagick
// pipe: a library, no external program at run time). GIF holds at most 256
// colours per frame, so each frame gets its own palette: the 256 most common
// colours at 5 bits per channel (the panels' flat colours exactly, shading with
// slight banding), every pixel mapped to the nearest of them. The file appears
// whole or not at all (app/output_file.h).
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "app/output_file.h"

namespace gridcull {

class GifWriter {
public:
    GifWriter();
    ~GifWriter();
    GifWriter(const GifWriter&) = delete;
    GifWriter& operator=(const GifWriter&) = delete;

    // width and height 1 to 65535.
    bool open(const std::string& path, int width, int height, std::string& error);
    // `rgba`: width * height * 4 bytes, rows from the top; shown `delay_cs`
    // hundredths of a second.
    bool addFrame(const std::vector<uint8_t>& rgba, int delay_cs, std::string& error);
    // Finishes the file and puts it in place.
    bool close(std::string& error);

private:
    struct Encoder;
    std::unique_ptr<Encoder> encoder_;
    OutputFile file_;
    int width_ = 0, height_ = 0;
    std::string path_;
};

// The per-frame palette: up to 256 RGB triples in `palette` and one index per
// pixel in `indices` (exposed for tests).
void quantizeFrame(const std::vector<uint8_t>& rgba, std::vector<uint8_t>& palette,
                   std::vector<uint8_t>& indices);

}  // namespace gridcull
