// The OSMesa side of the offscreen renderer: one OSMesa context per clm3d_render_context, the mesh
// in vertex buffers, fixed-function lighting and texturing. Every GL entry point is fetched with
// OSMesaGetProcAddress, so nothing here binds to a process-wide libGL.
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <new>
#include <string>
#include <vector>

#include "core/render/detail/render_module_abi.h"

namespace {

struct GlFunctions {
  decltype(&::glBindTexture) BindTexture = nullptr;
  decltype(&::glClear) Clear = nullptr;
  decltype(&::glClearColor) ClearColor = nullptr;
  decltype(&::glClearDepth) ClearDepth = nullptr;
  decltype(&::glDeleteTextures) DeleteTextures = nullptr;
  decltype(&::glDepthFunc) DepthFunc = nullptr;
  decltype(&::glDisable) Disable = nullptr;
  decltype(&::glDisableClientState) DisableClientState = nullptr;
  decltype(&::glDrawElements) DrawElements = nullptr;
  decltype(&::glEnable) Enable = nullptr;
  decltype(&::glEnableClientState) EnableClientState = nullptr;
  decltype(&::glFinish) Finish = nullptr;
  decltype(&::glGenTextures) GenTextures = nullptr;
  decltype(&::glGetError) GetError = nullptr;
  decltype(&::glGetIntegerv) GetIntegerv = nullptr;
  decltype(&::glGetString) GetString = nullptr;
  decltype(&::glLightModelfv) LightModelfv = nullptr;
  decltype(&::glLightModeli) LightModeli = nullptr;
  decltype(&::glLightfv) Lightfv = nullptr;
  decltype(&::glLoadIdentity) LoadIdentity = nullptr;
  decltype(&::glLoadMatrixd) LoadMatrixd = nullptr;
  decltype(&::glMaterialfv) Materialfv = nullptr;
  decltype(&::glMatrixMode) MatrixMode = nullptr;
  decltype(&::glNormalPointer) NormalPointer = nullptr;
  decltype(&::glPixelStorei) PixelStorei = nullptr;
  decltype(&::glReadPixels) ReadPixels = nullptr;
  decltype(&::glShadeModel) ShadeModel = nullptr;
  decltype(&::glTexCoordPointer) TexCoordPointer = nullptr;
  decltype(&::glTexEnvi) TexEnvi = nullptr;
  decltype(&::glTexImage2D) TexImage2D = nullptr;
  decltype(&::glTexParameteri) TexParameteri = nullptr;
  decltype(&::glVertexPointer) VertexPointer = nullptr;
  decltype(&::glViewport) Viewport = nullptr;
  PFNGLGENBUFFERSPROC GenBuffers = nullptr;
  PFNGLBINDBUFFERPROC BindBuffer = nullptr;
  PFNGLBUFFERDATAPROC BufferData = nullptr;
  PFNGLDELETEBUFFERSPROC DeleteBuffers = nullptr;
  PFNGLGENERATEMIPMAPPROC GenerateMipmap = nullptr;
};

GlFunctions gl;
std::once_flag glOnce;
std::string glLoadError;  // empty when every function was found
std::once_flag descriptionOnce;
std::string glDescription = "OSMesa (no context created yet)";

template <typename F>
void loadFunction(F& function, const char* name) {
  function = reinterpret_cast<F>(OSMesaGetProcAddress(name));
  if (function == nullptr) glLoadError += std::string(glLoadError.empty() ? "" : ", ") + name;
}

void loadGl() {
  loadFunction(gl.BindTexture, "glBindTexture");
  loadFunction(gl.Clear, "glClear");
  loadFunction(gl.ClearColor, "glClearColor");
  loadFunction(gl.ClearDepth, "glClearDepth");
  loadFunction(gl.DeleteTextures, "glDeleteTextures");
  loadFunction(gl.DepthFunc, "glDepthFunc");
  loadFunction(gl.Disable, "glDisable");
  loadFunction(gl.DisableClientState, "glDisableClientState");
  loadFunction(gl.DrawElements, "glDrawElements");
  loadFunction(gl.Enable, "glEnable");
  loadFunction(gl.EnableClientState, "glEnableClientState");
  loadFunction(gl.Finish, "glFinish");
  loadFunction(gl.GenTextures, "glGenTextures");
  loadFunction(gl.GetError, "glGetError");
  loadFunction(gl.GetIntegerv, "glGetIntegerv");
  loadFunction(gl.GetString, "glGetString");
  loadFunction(gl.LightModelfv, "glLightModelfv");
  loadFunction(gl.LightModeli, "glLightModeli");
  loadFunction(gl.Lightfv, "glLightfv");
  loadFunction(gl.LoadIdentity, "glLoadIdentity");
  loadFunction(gl.LoadMatrixd, "glLoadMatrixd");
  loadFunction(gl.Materialfv, "glMaterialfv");
  loadFunction(gl.MatrixMode, "glMatrixMode");
  loadFunction(gl.NormalPointer, "glNormalPointer");
  loadFunction(gl.PixelStorei, "glPixelStorei");
  loadFunction(gl.ReadPixels, "glReadPixels");
  loadFunction(gl.ShadeModel, "glShadeModel");
  loadFunction(gl.TexCoordPointer, "glTexCoordPointer");
  loadFunction(gl.TexEnvi, "glTexEnvi");
  loadFunction(gl.TexImage2D, "glTexImage2D");
  loadFunction(gl.TexParameteri, "glTexParameteri");
  loadFunction(gl.VertexPointer, "glVertexPointer");
  loadFunction(gl.Viewport, "glViewport");
  loadFunction(gl.GenBuffers, "glGenBuffers");
  loadFunction(gl.BindBuffer, "glBindBuffer");
  loadFunction(gl.BufferData, "glBufferData");
  loadFunction(gl.DeleteBuffers, "glDeleteBuffers");
  loadFunction(gl.GenerateMipmap, "glGenerateMipmap");
  if (!glLoadError.empty()) glLoadError = "OSMesa lacks GL functions: " + glLoadError;
}

void setError(char* error, std::size_t size, const std::string& message) {
  if (error == nullptr || size == 0) return;
  std::snprintf(error, size, "%s", message.c_str());
}

std::string glErrorText(GLenum code) {
  switch (code) {
    case GL_INVALID_ENUM:
      return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE:
      return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION:
      return "GL_INVALID_OPERATION";
    case GL_OUT_OF_MEMORY:
      return "GL_OUT_OF_MEMORY";
    default:
      return "GL error " + std::to_string(code);
  }
}

// Releases the calling thread's current context on scope exit, so a renderer can move between
// threads and never leaves a dangling current context behind.
struct ReleaseCurrent {
  ~ReleaseCurrent() { OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0); }
};

}  // namespace

struct clm3d_render_context {
  OSMesaContext osmesa = nullptr;
  std::vector<unsigned char> colour;  // the OSMesa colour buffer
  int width = 0;
  int height = 0;
  GLuint buffers[4] = {0, 0, 0, 0};  // positions, normals, uvs, indices
  GLuint texture = 0;
  GLsizei indexCount = 0;

  bool makeCurrent(int w, int h) {
    if (w != width || h != height) {
      colour.assign(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4, 0);
      width = w;
      height = h;
    }
    return OSMesaMakeCurrent(osmesa, colour.data(), GL_UNSIGNED_BYTE, w, h) == GL_TRUE;
  }
};

namespace {

bool upload(clm3d_render_context& context, const clm3d_render_mesh& mesh, std::string& error) {
  const auto vertices = static_cast<GLsizeiptr>(mesh.vertex_count);
  gl.GenBuffers(4, context.buffers);
  gl.BindBuffer(GL_ARRAY_BUFFER, context.buffers[0]);
  gl.BufferData(GL_ARRAY_BUFFER, vertices * 3 * 4, mesh.positions, GL_STATIC_DRAW);
  gl.BindBuffer(GL_ARRAY_BUFFER, context.buffers[1]);
  gl.BufferData(GL_ARRAY_BUFFER, vertices * 3 * 4, mesh.normals, GL_STATIC_DRAW);
  gl.BindBuffer(GL_ARRAY_BUFFER, context.buffers[2]);
  gl.BufferData(GL_ARRAY_BUFFER, vertices * 2 * 4, mesh.uvs, GL_STATIC_DRAW);
  gl.BindBuffer(GL_ARRAY_BUFFER, 0);
  gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, context.buffers[3]);
  gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.triangle_count) * 3 * 4,
                mesh.indices, GL_STATIC_DRAW);
  gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
  context.indexCount = static_cast<GLsizei>(mesh.triangle_count * 3);

  GLint maxSize = 0;
  gl.GetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  if (mesh.texture_width > maxSize || mesh.texture_height > maxSize) {
    error = "texture of " + std::to_string(mesh.texture_width) + "x" +
            std::to_string(mesh.texture_height) + " exceeds the GL limit of " +
            std::to_string(maxSize);
    return false;
  }
  // OpenGL's first texture row is the bottom one (t = 0); ours is the top one: flip on upload.
  const std::size_t rowBytes = static_cast<std::size_t>(mesh.texture_width) * 3;
  std::vector<unsigned char> flipped(rowBytes * static_cast<std::size_t>(mesh.texture_height));
  for (int row = 0; row < mesh.texture_height; ++row) {
    std::memcpy(flipped.data() + rowBytes * static_cast<std::size_t>(mesh.texture_height - 1 - row),
                mesh.texture_bgr + rowBytes * static_cast<std::size_t>(row), rowBytes);
  }
  // Repeat only if the UVs ask for it; clamping avoids bleeding across the edges of an atlas.
  bool repeat = false;
  for (std::size_t i = 0; i < static_cast<std::size_t>(mesh.vertex_count) * 2; ++i) {
    if (mesh.uvs[i] < -1e-3F || mesh.uvs[i] > 1.001F) repeat = true;
  }
  gl.GenTextures(1, &context.texture);
  gl.BindTexture(GL_TEXTURE_2D, context.texture);
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, mesh.texture_width, mesh.texture_height, 0, GL_BGR,
                GL_UNSIGNED_BYTE, flipped.data());
  gl.GenerateMipmap(GL_TEXTURE_2D);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  const GLint wrap = repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE;
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap);
  gl.BindTexture(GL_TEXTURE_2D, 0);
  if (const GLenum code = gl.GetError(); code != GL_NO_ERROR) {
    error = "uploading the mesh failed: " + glErrorText(code);
    return false;
  }
  return true;
}

clm3d_render_context* create(const clm3d_render_mesh* mesh, char* error, size_t errorSize) {
  std::call_once(glOnce, loadGl);
  if (!glLoadError.empty()) {
    setError(error, errorSize, glLoadError);
    return nullptr;
  }
  if (mesh == nullptr || mesh->vertex_count == 0 || mesh->triangle_count == 0 ||
      mesh->texture_bgr == nullptr || mesh->texture_width <= 0 || mesh->texture_height <= 0) {
    setError(error, errorSize, "empty mesh or texture");
    return nullptr;
  }
  auto* context = new (std::nothrow) clm3d_render_context;
  if (context == nullptr) {
    setError(error, errorSize, "out of memory");
    return nullptr;
  }
  context->osmesa = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  if (context->osmesa == nullptr) {
    delete context;
    setError(error, errorSize, "OSMesaCreateContextExt failed");
    return nullptr;
  }
  ReleaseCurrent release;
  if (!context->makeCurrent(16, 16)) {
    OSMesaDestroyContext(context->osmesa);
    delete context;
    setError(error, errorSize, "OSMesaMakeCurrent failed");
    return nullptr;
  }
  std::call_once(descriptionOnce, [] {
    const auto* renderer = reinterpret_cast<const char*>(gl.GetString(GL_RENDERER));
    const auto* version = reinterpret_cast<const char*>(gl.GetString(GL_VERSION));
    glDescription = std::string("OSMesa, ") + (renderer != nullptr ? renderer : "?") + ", GL " +
                    (version != nullptr ? version : "?");
  });
  std::string message;
  if (!upload(*context, *mesh, message)) {
    OSMesaDestroyContext(context->osmesa);
    delete context;
    setError(error, errorSize, message);
    return nullptr;
  }
  return context;
}

int draw(clm3d_render_context* context, const clm3d_render_frame* frame, char* error,
         size_t errorSize) {
  if (context == nullptr || frame == nullptr || frame->width <= 0 || frame->height <= 0 ||
      frame->out_rgba == nullptr || frame->out_depth == nullptr) {
    setError(error, errorSize, "invalid draw request");
    return 1;
  }
  ReleaseCurrent release;
  if (!context->makeCurrent(frame->width, frame->height)) {
    setError(error, errorSize,
             "OSMesaMakeCurrent failed for " + std::to_string(frame->width) + "x" +
                 std::to_string(frame->height));
    return 1;
  }
  gl.Viewport(0, 0, frame->width, frame->height);
  gl.ClearColor(0.0F, 0.0F, 0.0F, 0.0F);  // transparent background: alpha = coverage
  gl.ClearDepth(1.0);
  gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthFunc(GL_LESS);
  gl.Disable(GL_CULL_FACE);  // scans are often open or inconsistently wound
  gl.Disable(GL_BLEND);
  gl.ShadeModel(GL_SMOOTH);

  gl.MatrixMode(GL_PROJECTION);
  gl.LoadMatrixd(frame->projection);
  gl.MatrixMode(GL_MODELVIEW);
  gl.LoadIdentity();  // the light is given in eye space

  float dir[3] = {frame->light_direction[0], frame->light_direction[1], frame->light_direction[2]};
  const float norm = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
  if (norm > 0.0F) {
    for (float& d : dir) d /= norm;
  } else {
    dir[2] = 1.0F;
  }
  const float position[4] = {dir[0], dir[1], dir[2], 0.0F};
  const float ambient[4] = {frame->ambient, frame->ambient, frame->ambient, 1.0F};
  const float diffuse[4] = {frame->diffuse, frame->diffuse, frame->diffuse, 1.0F};
  const float zero[4] = {0.0F, 0.0F, 0.0F, 1.0F};
  const float white[4] = {1.0F, 1.0F, 1.0F, 1.0F};
  gl.Enable(GL_LIGHTING);
  gl.Enable(GL_LIGHT0);
  gl.Lightfv(GL_LIGHT0, GL_POSITION, position);
  gl.Lightfv(GL_LIGHT0, GL_AMBIENT, ambient);
  gl.Lightfv(GL_LIGHT0, GL_DIFFUSE, diffuse);
  gl.Lightfv(GL_LIGHT0, GL_SPECULAR, zero);
  gl.LightModelfv(GL_LIGHT_MODEL_AMBIENT, zero);
  gl.LightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  gl.Materialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, white);
  gl.Materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, zero);
  gl.Materialfv(GL_FRONT_AND_BACK, GL_EMISSION, zero);
  gl.Enable(GL_NORMALIZE);  // the model-view matrix may scale

  gl.LoadMatrixd(frame->modelview);
  gl.Enable(GL_TEXTURE_2D);
  gl.BindTexture(GL_TEXTURE_2D, context->texture);
  gl.TexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);

  gl.EnableClientState(GL_VERTEX_ARRAY);
  gl.EnableClientState(GL_NORMAL_ARRAY);
  gl.EnableClientState(GL_TEXTURE_COORD_ARRAY);
  gl.BindBuffer(GL_ARRAY_BUFFER, context->buffers[0]);
  gl.VertexPointer(3, GL_FLOAT, 0, nullptr);
  gl.BindBuffer(GL_ARRAY_BUFFER, context->buffers[1]);
  gl.NormalPointer(GL_FLOAT, 0, nullptr);
  gl.BindBuffer(GL_ARRAY_BUFFER, context->buffers[2]);
  gl.TexCoordPointer(2, GL_FLOAT, 0, nullptr);
  gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, context->buffers[3]);
  gl.DrawElements(GL_TRIANGLES, context->indexCount, GL_UNSIGNED_INT, nullptr);
  gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
  gl.BindBuffer(GL_ARRAY_BUFFER, 0);
  gl.DisableClientState(GL_VERTEX_ARRAY);
  gl.DisableClientState(GL_NORMAL_ARRAY);
  gl.DisableClientState(GL_TEXTURE_COORD_ARRAY);
  gl.BindTexture(GL_TEXTURE_2D, 0);

  gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl.ReadPixels(0, 0, frame->width, frame->height, GL_RGBA, GL_UNSIGNED_BYTE, frame->out_rgba);
  gl.ReadPixels(0, 0, frame->width, frame->height, GL_DEPTH_COMPONENT, GL_FLOAT, frame->out_depth);
  if (const GLenum code = gl.GetError(); code != GL_NO_ERROR) {
    setError(error, errorSize, "drawing failed: " + glErrorText(code));
    return 1;
  }
  return 0;
}

void destroy(clm3d_render_context* context) {
  if (context == nullptr) return;
  {
    ReleaseCurrent release;
    if (context->makeCurrent(context->width > 0 ? context->width : 16,
                             context->height > 0 ? context->height : 16)) {
      gl.DeleteBuffers(4, context->buffers);
      if (context->texture != 0) gl.DeleteTextures(1, &context->texture);
    }
  }
  OSMesaDestroyContext(context->osmesa);
  delete context;
}

const char* describe() {
  return glDescription.c_str();
}

const clm3d_render_api kApi = {CLM3D_RENDER_ABI_VERSION, create, draw, destroy, describe};

}  // namespace

extern "C" __attribute__((visibility("default"))) const clm3d_render_api*
clm3d_render_module_api() {
  return &kApi;
}
