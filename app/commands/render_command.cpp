// clm3d render: a textured mesh drawn offscreen at a head pose, framed automatically, with its
// projected landmarks, depth map and overlay on demand. The options and the work are core's
// (core/dataset/render_request); this file adds them and prints what core says.

#include "app/commands/commands.hpp"
#include "app/commands/option_cli.hpp"
#include "core/dataset/render_request.hpp"

namespace clm3d::cli {

void addRenderCommand(CLI::App& root) {
  addRequestCommand(root, "render",
                    "Render a textured mesh offscreen at a head pose (transparent PNG), with "
                    "optional projected landmarks, depth map and landmark overlay",
                    renderOptions(), [](const RenderRequest& request, const CLI::App&) {
                      return runRender(request);
                    });
}

}  // namespace clm3d::cli
