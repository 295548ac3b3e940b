// An output file that appears whole or not at all: text goes to a temporary file
// beside the target, renamed over it by commit(). Destroyed without commit(), the
// temporary is removed, so a failed or interrupted command leaves no partial file.
#pragma once
#include <cstdio>
#include <string>

namespace gridcull {

class OutputFile {
public:
    OutputFile() = default;
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;
    ~OutputFile();

    // Opens a temporary next to `path`. Returns false and sets `error` on failure.
    bool open(const std::string& path, std::string& error);
    std::FILE* stream() const { return file_; }
    // Flushes, closes and renames into place. Returns false and sets `error` on failure.
    bool commit(std::string& error);

private:
    std::FILE* file_ = nullptr;
    std::string path_;
    std::string temp_path_;
};

// A temporary name in the same folder as `path` (so that rename stays atomic).
std::string temporarySibling(const std::string& path);

}  // namespace gridcull
