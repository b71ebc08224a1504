// clm3d ict-texture: registers the ICT-FaceKit neutral onto a textured scan and bakes the scan's
// texture into ICT's UV layout. The options and the work are core's (core/dataset/
// ict_texture_request); this file adds them and prints the report.

#include "app/commands/commands.hpp"
#include "app/commands/option_cli.hpp"
#include "core/dataset/ict_texture_request.hpp"

namespace clm3d::cli {

void addIctTextureCommand(CLI::App& root) {
  addRequestCommand(root, "ict-texture",
                    "Register the ICT-FaceKit neutral mesh onto a textured scan and bake the "
                    "scan's texture into ICT's UV layout (writes OBJ + MTL + PNG; see "
                    "docs/texture-transfer.md)",
                    ictTextureOptions(), [](const IctTextureRequest& request, const CLI::App&) {
                      return runIctTexture(request);
                    });
}

}  // namespace clm3d::cli
