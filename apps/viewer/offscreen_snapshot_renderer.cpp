// simplify --snapshot's renderer (cli/Snapshot_renderer.h): the viewer's offscreen picture.
#include "cli/Snapshot_renderer.h"
#include "snapshot.h"

namespace apps {
namespace {

class Offscreen_snapshot_renderer : public Snapshot_renderer {
 public:
  Offscreen_snapshot_renderer(int width, int height) {
    m_settings.width = width;
    m_settings.height = height;
  }

  std::vector<std::string> prepare(const Mesh& input,
                                   const Material_references& materials) override {
    std::vector<std::string> left_out;
    m_settings.texture = texture_to_draw(input, materials, left_out);
    return left_out;
  }

  void write(const Mesh& input, const Mesh& output, const std::string& name,
             const std::string& png) override {
    Snapshot_settings settings = m_settings;
    caption_snapshot(input, output, name, settings);
    write_snapshot(input, output, settings, png);
  }

 private:
  Snapshot_settings m_settings;
};

}  // namespace

std::unique_ptr<Snapshot_renderer> make_snapshot_renderer(int width, int height) {
  return std::make_unique<Offscreen_snapshot_renderer>(width, height);
}

bool snapshots_in_this_build() { return true; }

}  // namespace apps
