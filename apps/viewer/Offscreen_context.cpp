#include "Offscreen_context.h"

#include <GL/osmesa.h>
#include <dlfcn.h>

#include <stdexcept>
#include <string>

namespace apps {
namespace {

// OSMesa is opened when the first picture is asked for: linked, it brings LLVM along, whose
// relocation made up most of the start of every run of the tools that can draw.
struct Osmesa_library {
  decltype(&OSMesaCreateContextAttribs) create_context;
  decltype(&OSMesaMakeCurrent) make_current;
  decltype(&OSMesaDestroyContext) destroy_context;
  decltype(&OSMesaGetProcAddress) proc_address;
};

template <typename Function>
void find_function(void* library, const char* name, Function& function) {
  void* const found = dlsym(library, name);
  if (found == nullptr)
    throw std::runtime_error(std::string("OSMesa has no ") + name + " (" +
                             CGAL_POLICIES_OSMESA_LIBRARY + ")");
  function = reinterpret_cast<Function>(found);
}

Osmesa_library open_osmesa() {
  void* const library = dlopen(CGAL_POLICIES_OSMESA_LIBRARY, RTLD_NOW | RTLD_LOCAL);
  if (library == nullptr) throw std::runtime_error(std::string("cannot open OSMesa: ") + dlerror());
  Osmesa_library osmesa;
  find_function(library, "OSMesaCreateContextAttribs", osmesa.create_context);
  find_function(library, "OSMesaMakeCurrent", osmesa.make_current);
  find_function(library, "OSMesaDestroyContext", osmesa.destroy_context);
  find_function(library, "OSMesaGetProcAddress", osmesa.proc_address);
  return osmesa;
}

// Opened once, and kept open: the contexts' GL functions live in it.
const Osmesa_library& osmesa() {
  static const Osmesa_library library = open_osmesa();
  return library;
}

}  // namespace

struct Offscreen_context::Impl {
  OSMesaContext context = nullptr;
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // OSMesa renders straight into it, bottom row first
};

Offscreen_context::Offscreen_context(int width, int height) : m_impl(std::make_unique<Impl>()) {
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,
                            24,
                            OSMESA_PROFILE,
                            OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            3,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            3,
                            0};
  m_impl->context = osmesa().create_context(attributes, nullptr);
  if (!m_impl->context) throw std::runtime_error("OSMesa offers no OpenGL 3.3 core context");
  m_impl->width = width;
  m_impl->height = height;
  m_impl->rgba.resize(std::size_t(width) * std::size_t(height) * 4);
  if (!osmesa().make_current(m_impl->context, m_impl->rgba.data(), GL_UNSIGNED_BYTE, width,
                             height)) {
    osmesa().destroy_context(m_impl->context);
    throw std::runtime_error("OSMesa cannot render a " + std::to_string(width) + "x" +
                             std::to_string(height) + " picture");
  }
}

Offscreen_context::~Offscreen_context() { osmesa().destroy_context(m_impl->context); }

Gl_loader Offscreen_context::loader() const {
  return [](const char* name) { return Gl_proc(osmesa().proc_address(name)); };
}

std::vector<std::uint8_t> Offscreen_context::rgb_pixels() const {
  const std::size_t w = std::size_t(m_impl->width), h = std::size_t(m_impl->height);
  std::vector<std::uint8_t> rgb(w * h * 3);
  for (std::size_t y = 0; y < h; ++y)
    for (std::size_t x = 0; x < w; ++x)
      for (std::size_t c = 0; c < 3; ++c)
        rgb[(y * w + x) * 3 + c] = m_impl->rgba[((h - 1 - y) * w + x) * 4 + c];
  return rgb;
}

}  // namespace apps
