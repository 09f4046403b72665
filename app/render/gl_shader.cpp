#include "gl_shader.h"

#include <vector>

namespace {

std::string shaderLog(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<std::size_t>(length > 1 ? length : 1), '\0');
    glGetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
    return log.data();
}

std::string programLog(GLuint program) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<std::size_t>(length > 1 ? length : 1), '\0');
    glGetProgramInfoLog(program, static_cast<GLsizei>(log.size()), nullptr, log.data());
    return log.data();
}

GLuint compile(GLenum type, const char* source, const std::string& name, std::string* error) {
    const GLuint shader = glCreateShader(type);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        if (error) *error = name + ": " + shaderLog(shader);
        glDeleteShader(shader);
        return 0;
    }
    return shader;
}

// The source with `defines` inserted after its first line (the #version line).
std::string withDefines(const char* source, const char* defines) {
    std::string text = source;
    if (!*defines) return text;
    const std::size_t eol = text.find('\n');
    text.insert(eol == std::string::npos ? text.size() : eol + 1, defines);
    return text;
}

} // namespace

GLuint buildProgram(const char* vertexSource, const char* fragmentSource, const char* name,
                    std::string* error, const char* defines) {
    const std::string base = name;
    const std::string vertex = withDefines(vertexSource, defines);
    const GLuint vs = compile(GL_VERTEX_SHADER, vertex.c_str(), base + ".vert", error);
    if (!vs) return 0;
    const std::string fragment = withDefines(fragmentSource, defines);
    const GLuint fs = compile(GL_FRAGMENT_SHADER, fragment.c_str(), base + ".frag", error);
    if (!fs) {
        glDeleteShader(vs);
        return 0;
    }
    const GLuint program = glCreateProgram();
    glAttachShader(program, vs);
    glAttachShader(program, fs);
    glLinkProgram(program);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        if (error) *error = base + " (link): " + programLog(program);
        glDeleteProgram(program);
        return 0;
    }
    return program;
}
