#include "app/png_file.h"

#include <cstdio>

#include <stb_image_write.h>

#include "app/output_file.h"

namespace gridcull {

namespace {

void writeToFile(void* context, void* data, int size) {
    std::fwrite(data, 1, size_t(size), static_cast<std::FILE*>(context));
}

}  // namespace

bool writePngFile(const std::string& path, int width, int height,
                  const std::vector<uint8_t>& rgba, std::string& error) {
    if (rgba.size() != size_t(width) * size_t(height) * 4) {
        error = "internal: pixel buffer does not match the image size";
        return false;
    }
    OutputFile file;
    if (!file.open(path, error)) return false;
    if (!stbi_write_png_to_func(writeToFile, file.stream(), width, height, 4, rgba.data(),
                                width * 4)) {
        error = "cannot encode '" + path + "' as PNG";
        return false;  // `file` removes its temporary
    }
    return file.commit(error);
}

}  // namespace gridcull
