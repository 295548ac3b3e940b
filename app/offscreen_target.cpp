#include "app/offscreen_target.h"

#include <cstring>

namespace gridcull {

bool OffscreenTarget::create(int width, int height, std::string& error) {
    GLint max_size = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
    if (width <= 0 || height <= 0 || width > max_size || height > max_size) {
        error = "image size " + std::to_string(width) + "x" + std::to_string(height) +
                " is outside what OpenGL renders (1.." + std::to_string(max_size) + ")";
        return false;
    }
    width_ = width;
    height_ = height;
    GLuint ids[2] = {0, 0};
    glGenRenderbuffers(2, ids);
    color_ = GlRenderbuffer(ids[0]);
    depth_ = GlRenderbuffer(ids[1]);
    glBindRenderbuffer(GL_RENDERBUFFER, color_.get());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_.get());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    GLuint fbo = 0;
    glGenFramebuffers(1, &fbo);
    framebuffer_ = GlFramebuffer(fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_.get());
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.get());
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        error = "off-screen framebuffer incomplete (status " + std::to_string(status) + ")";
        return false;
    }
    return true;
}

void OffscreenTarget::bind() const { glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get()); }

void OffscreenTarget::readPixelsTopDown(std::vector<uint8_t>& rgba) const {
    const size_t row = size_t(width_) * 4;
    rgba.resize(row * size_t(height_));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.get());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    // GL's rows start at the bottom; PNG's at the top.
    std::vector<uint8_t> swap(row);
    for (int y = 0; y < height_ / 2; ++y) {
        uint8_t* a = rgba.data() + size_t(y) * row;
        uint8_t* b = rgba.data() + size_t(height_ - 1 - y) * row;
        std::memcpy(swap.data(), a, row);
        std::memcpy(a, b, row);
        std::memcpy(b, swap.data(), row);
    }
}

}  // namespace gridcull
