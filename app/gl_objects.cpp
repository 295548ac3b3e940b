#include "app/gl_objects.h"

#include <vector>

namespace gridcull {

void deleteGlBuffer(GLuint id) { glDeleteBuffers(1, &id); }
void deleteGlVertexArray(GLuint id) { glDeleteVertexArrays(1, &id); }
void deleteGlProgram(GLuint id) { glDeleteProgram(id); }
void deleteGlFramebuffer(GLuint id) { glDeleteFramebuffers(1, &id); }
void deleteGlRenderbuffer(GLuint id) { glDeleteRenderbuffers(1, &id); }

GlBuffer makeGlBuffer() {
    GLuint id = 0;
    glGenBuffers(1, &id);
    return GlBuffer(id);
}

GlVertexArray makeGlVertexArray() {
    GLuint id = 0;
    glGenVertexArrays(1, &id);
    return GlVertexArray(id);
}

namespace {

std::string shaderLog(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(size_t(length > 1 ? length : 1), '\0');
    glGetShaderInfoLog(shader, GLsizei(log.size()), nullptr, log.data());
    return log.data();
}

GLuint compile(GLenum kind, const char* source, std::string& error) {
    const GLuint shader = glCreateShader(kind);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        error = std::string(kind == GL_VERTEX_SHADER ? "vertex" : "fragment") +
                " shader does not compile: " + shaderLog(shader);
        glDeleteShader(shader);
        return 0;
    }
    return shader;
}

}  // namespace

GlProgram buildGlProgram(const char* vertex_source, const char* fragment_source,
                         std::string& error) {
    const GLuint vs = compile(GL_VERTEX_SHADER, vertex_source, error);
    if (!vs) return GlProgram();
    const GLuint fs = compile(GL_FRAGMENT_SHADER, fragment_source, error);
    if (!fs) {
        glDeleteShader(vs);
        return GlProgram();
    }
    GlProgram program(glCreateProgram());
    glAttachShader(program.get(), vs);
    glAttachShader(program.get(), fs);
    glLinkProgram(program.get());
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = GL_FALSE;
    glGetProgramiv(program.get(), GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetProgramiv(program.get(), GL_INFO_LOG_LENGTH, &length);
        std::vector<char> log(size_t(length > 1 ? length : 1), '\0');
        glGetProgramInfoLog(program.get(), GLsizei(log.size()), nullptr, log.data());
        error = std::string("shader program does not link: ") + log.data();
        return GlProgram();
    }
    return program;
}

void StreamBuffer::init(GLenum target) {
    target_ = target;
    buffer_ = makeGlBuffer();
    capacity_ = 0;
}

void StreamBuffer::upload(const void* data, size_t bytes) {
    glBindBuffer(target_, buffer_.get());
    if (bytes > capacity_) {
        // Grow by half again so a slowly growing PVS does not reallocate every frame.
        capacity_ = bytes + bytes / 2;
        glBufferData(target_, GLsizeiptr(capacity_), nullptr, GL_STREAM_DRAW);
    }
    if (bytes > 0) glBufferSubData(target_, 0, GLsizeiptr(bytes), data);
}

}  // namespace gridcull
