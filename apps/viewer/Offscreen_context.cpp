#include "Offscreen_context.h"

#include <GL/osmesa.h>

#include <stdexcept>

namespace apps {

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
  m_impl->context = OSMesaCreateContextAttribs(attributes, nullptr);
  if (!m_impl->context) throw std::runtime_error("OSMesa offers no OpenGL 3.3 core context");
  m_impl->width = width;
  m_impl->height = height;
  m_impl->rgba.resize(std::size_t(width) * std::size_t(height) * 4);
  if (!OSMesaMakeCurrent(m_impl->context, m_impl->rgba.data(), GL_UNSIGNED_BYTE, width, height)) {
    OSMesaDestroyContext(m_impl->context);
    throw std::runtime_error("OSMesa cannot render a " + std::to_string(width) + "x" +
                             std::to_string(height) + " picture");
  }
}

Offscreen_context::~Offscreen_context() { OSMesaDestroyContext(m_impl->context); }

Gl_loader Offscreen_context::loader() const {
  return [](const char* name) { return Gl_proc(OSMesaGetProcAddress(name)); };
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
