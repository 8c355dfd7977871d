// The renderer of a build without the viewer's packages (apps/viewer/CMakeLists.txt): none.
#include "Snapshot_renderer.h"

namespace apps {

std::unique_ptr<Snapshot_renderer> make_snapshot_renderer(int, int) { return nullptr; }

bool snapshots_in_this_build() { return false; }

}  // namespace apps
