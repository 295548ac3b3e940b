// Owning handles for OpenGL objects (move-only; deleted with the object) and the
// shader program helper. Need a current context for every call except moves.
#pragma once
#include <string>
#include <utility>

#include "app/gl_api.h"

namespace gridcull {

template <void (*Delete)(GLuint)>
class GlHandle {
public:
    GlHandle() = default;
    explicit GlHandle(GLuint id) : id_(id) {}
    GlHandle(GlHandle&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
    GlHandle& operator=(GlHandle&& other) noexcept {
        if (this != &other) {
            reset();
            id_ = std::exchange(other.id_, 0);
        }
        return *this;
    }
    GlHandle(const GlHandle&) = delete;
    GlHandle& operator=(const GlHandle&) = delete;
    ~GlHandle() { reset(); }

    GLuint get() const { return id_; }
    void reset() {
        if (id_) Delete(id_);
        id_ = 0;
    }

private:
    GLuint id_ = 0;
};

void deleteGlBuffer(GLuint id);
void deleteGlVertexArray(GLuint id);
void deleteGlProgram(GLuint id);
void deleteGlFramebuffer(GLuint id);
void deleteGlRenderbuffer(GLuint id);

using GlBuffer = GlHandle<deleteGlBuffer>;
using GlVertexArray = GlHandle<deleteGlVertexArray>;
using GlProgram = GlHandle<deleteGlProgram>;
using GlFramebuffer = GlHandle<deleteGlFramebuffer>;
using GlRenderbuffer = GlHandle<deleteGlRenderbuffer>;

GlBuffer makeGlBuffer();
GlVertexArray makeGlVertexArray();

// Compiles and links a vertex + fragment shader pair. On failure returns an empty
// program and puts the driver's log in `error`.
GlProgram buildGlProgram(const char* vertex_source, const char* fragment_source,
                         std::string& error);

// A buffer whose contents are replaced every frame. It keeps its storage and only
// reallocates when a frame needs more bytes than any before, so a steady state
// uploads with glBufferSubData and allocates nothing.
class StreamBuffer {
public:
    void init(GLenum target);
    // Binds the buffer and copies `bytes` bytes from `data` into it.
    void upload(const void* data, size_t bytes);
    GLuint id() const { return buffer_.get(); }

private:
    GlBuffer buffer_;
    GLenum target_ = GL_ARRAY_BUFFER;
    size_t capacity_ = 0;
};

}  // namespace gridcull
