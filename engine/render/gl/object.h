#pragma once
// Move-only RAII ownership of OpenGL objects. An empty object (id 0) is valid and owns nothing;
// moving leaves the source empty. GL thread only.

#include <epoxy/gl.h>

#include <utility>

namespace terrasol::gl {

template <class Traits>
class Object {
 public:
  Object() = default;
  // Creates a new GL object; arguments go to the create call (e.g. a texture target).
  template <class... Args>
  static Object create(Args... args) {
    return Object(Traits::create(args...));
  }
  ~Object() { reset(); }

  Object(const Object&) = delete;
  Object& operator=(const Object&) = delete;
  Object(Object&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
  Object& operator=(Object&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, 0);
    }
    return *this;
  }

  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  void reset() {
    if (id_ != 0) Traits::destroy(id_);
    id_ = 0;
  }

 private:
  explicit Object(GLuint id) : id_(id) {}
  GLuint id_ = 0;
};

// Traits for the DSA (GL 4.5) create functions, which give fully initialised objects.
#define TERRASOL_GL_TRAITS(Name, createCall, destroyCall) \
  struct Name##Traits {                                   \
    template <class... Args>                              \
    static GLuint create(Args... args) {                  \
      GLuint id = 0;                                      \
      createCall;                                         \
      return id;                                          \
    }                                                     \
    static void destroy(GLuint id) { destroyCall; }       \
  };                                                      \
  using Name = Object<Name##Traits>;

TERRASOL_GL_TRAITS(Buffer, glCreateBuffers(1, &id), glDeleteBuffers(1, &id))
TERRASOL_GL_TRAITS(VertexArray, glCreateVertexArrays(1, &id), glDeleteVertexArrays(1, &id))
TERRASOL_GL_TRAITS(Texture, glCreateTextures(args..., 1, &id), glDeleteTextures(1, &id))
// A view of another texture's storage in a compatible format (arguments as glTextureView's after the
// name): the same texels read another way, e.g. an sRGB atlas as plain RGBA8.
TERRASOL_GL_TRAITS(TextureView, glGenTextures(1, &id); glTextureView(id, args...), glDeleteTextures(1, &id))
TERRASOL_GL_TRAITS(Renderbuffer, glCreateRenderbuffers(1, &id), glDeleteRenderbuffers(1, &id))
TERRASOL_GL_TRAITS(Framebuffer, glCreateFramebuffers(1, &id), glDeleteFramebuffers(1, &id))
TERRASOL_GL_TRAITS(Sampler, glCreateSamplers(1, &id), glDeleteSamplers(1, &id))
TERRASOL_GL_TRAITS(Query, glCreateQueries(args..., 1, &id), glDeleteQueries(1, &id))
TERRASOL_GL_TRAITS(Shader, id = glCreateShader(args...), glDeleteShader(id))
TERRASOL_GL_TRAITS(Program, id = glCreateProgram(args...), glDeleteProgram(id))

#undef TERRASOL_GL_TRAITS

}  // namespace terrasol::gl
