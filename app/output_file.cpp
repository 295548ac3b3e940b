#include "app/output_file.h"

#include <cerrno>
#include <cstring>
#include <unistd.h>

namespace gridcull {

std::string temporarySibling(const std::string& path) {
    return path + ".part-" + std::to_string(::getpid());
}

OutputFile::~OutputFile() {
    if (file_) {
        std::fclose(file_);
        std::remove(temp_path_.c_str());
    }
}

bool OutputFile::open(const std::string& path, std::string& error) {
    path_ = path;
    temp_path_ = temporarySibling(path);
    file_ = std::fopen(temp_path_.c_str(), "wb");
    if (!file_) {
        error = "cannot write '" + path + "': " + std::strerror(errno);
        return false;
    }
    return true;
}

bool OutputFile::commit(std::string& error) {
    const bool write_failed = std::ferror(file_) != 0;
    const bool close_failed = std::fclose(file_) != 0;
    file_ = nullptr;
    if (write_failed || close_failed) {
        std::remove(temp_path_.c_str());
        error = "writing '" + path_ + "' failed";
        return false;
    }
    if (std::rename(temp_path_.c_str(), path_.c_str()) != 0) {
        error = "cannot move output into '" + path_ + "': " + std::strerror(errno);
        std::remove(temp_path_.c_str());
        return false;
    }
    return true;
}

}  // namespace gridcull
