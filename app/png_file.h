// Writing a PNG so that it appears whole or not at all (app/output_file.h).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace gridcull {

// `rgba`: width * height * 4 bytes, rows from the top. Alpha is written as is.
// Returns false and sets `error` when the file cannot be written; no partial
// file is left behind then.
bool writePngFile(const std::string& path, int width, int height,
                  const std::vector<uint8_t>& rgba, std::string& error);

}  // namespace gridcull
