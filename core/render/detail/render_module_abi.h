/* The C interface between the renderer (core, clm3d_render) and the OSMesa module
 * (clm3d_render_osmesa), which is loaded with dlopen. Plain C types only, so the two sides need
 * not agree on a C++ ABI; the module exports one symbol, CLM3D_RENDER_MODULE_ENTRY, returning the
 * function table. Bump CLM3D_RENDER_ABI_VERSION on any change. */
#ifndef CLM3D_RENDER_MODULE_ABI_H
#define CLM3D_RENDER_MODULE_ABI_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define CLM3D_RENDER_ABI_VERSION 1
#define CLM3D_RENDER_MODULE_ENTRY "clm3d_render_module_api"

/* The mesh, copied by create(): vertex arrays (xyz, xyz, uv) and a tightly packed BGR texture
 * whose first row is the image's top row (the module flips it for OpenGL). */
typedef struct clm3d_render_mesh {
  const float* positions;
  const float* normals;
  const float* uvs;
  const uint32_t* indices;
  uint32_t vertex_count;
  uint32_t triangle_count;
  const unsigned char* texture_bgr;
  int texture_width;
  int texture_height;
} clm3d_render_mesh;

/* One draw. Matrices are column-major (OpenGL order). Outputs have width * height elements, row 0
 * at the bottom (OpenGL order): RGBA8 colour and window depth in [0, 1] (1 = background). */
typedef struct clm3d_render_frame {
  int width;
  int height;
  double modelview[16];
  double projection[16];
  float light_direction[3]; /* eye space, towards the light */
  float ambient;
  float diffuse;
  unsigned char* out_rgba;
  float* out_depth;
} clm3d_render_frame;

typedef struct clm3d_render_context clm3d_render_context;

typedef struct clm3d_render_api {
  int abi_version;
  /* Creates an OSMesa context and uploads the mesh. NULL on failure, with a message in error. */
  clm3d_render_context* (*create)(const clm3d_render_mesh* mesh, char* error, size_t error_size);
  /* Makes the context current on the calling thread, draws, reads back, releases the context.
   * Returns 0 on success, else writes a message to error. */
  int (*draw)(clm3d_render_context* context, const clm3d_render_frame* frame, char* error,
              size_t error_size);
  void (*destroy)(clm3d_render_context* context);
  /* A short description of the GL implementation (renderer and version strings). */
  const char* (*describe)(void);
} clm3d_render_api;

typedef const clm3d_render_api* (*clm3d_render_module_entry_fn)(void);

#ifdef __cplusplus
}
#endif

#endif
