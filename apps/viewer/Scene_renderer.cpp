#include "Scene_renderer.h"

#include <stb_easy_font.h>

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace apps {
namespace {

constexpr const char* kMeshVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 color;
layout(location = 3) in vec2 uv;
uniform mat4 model_view;
uniform mat4 projection;
out vec3 view_position;
out vec3 view_normal;
out vec3 base_color;
out vec2 texture_uv;
void main() {
  vec4 p = model_view * vec4(position, 1.0);
  view_position = p.xyz;
  view_normal = mat3(model_view) * normal;
  base_color = color;
  texture_uv = uv;
  gl_Position = projection * p;
}
)";

// A headlight: lit from the eye, both sides alike (meshes may be open).
constexpr const char* kMeshFragmentShader = R"(#version 330 core
in vec3 view_position;
in vec3 view_normal;
in vec3 base_color;
in vec2 texture_uv;
uniform int flat_shading;
uniform int solid;
uniform vec3 solid_color;
uniform int textured;
uniform sampler2D texture_map;
out vec4 fragment;
void main() {
  if (solid == 1) {
    fragment = vec4(solid_color, 1.0);
    return;
  }
  vec3 n = flat_shading == 1 ? cross(dFdx(view_position), dFdy(view_position)) : view_normal;
  float lit = abs(dot(normalize(n), normalize(-view_position)));
  vec3 surface = textured == 1 ? texture(texture_map, texture_uv).rgb : base_color;
  fragment = vec4(surface * (0.25 + 0.75 * lit) + vec3(0.12 * pow(lit, 24.0)), 1.0);
}
)";

// Captions and the legend, in pixels from the top-left corner.
constexpr const char* kOverlayVertexShader = R"(#version 330 core
layout(location = 0) in vec2 pixel;
layout(location = 1) in vec3 color;
uniform vec2 viewport;
out vec3 overlay_color;
void main() {
  overlay_color = color;
  gl_Position = vec4(2.0 * pixel.x / viewport.x - 1.0, 1.0 - 2.0 * pixel.y / viewport.y, 0.0, 1.0);
}
)";

constexpr const char* kOverlayFragmentShader = R"(#version 330 core
in vec3 overlay_color;
out vec4 fragment;
void main() { fragment = vec4(overlay_color, 1.0); }
)";

GLuint compile(const Gl_functions& gl, GLenum type, const char* source) {
  const GLuint shader = gl.CreateShader(type);
  gl.ShaderSource(shader, 1, &source, nullptr);
  gl.CompileShader(shader);
  GLint ok = 0;
  gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[1024] = {};
    gl.GetShaderInfoLog(shader, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("shader compilation failed: ") + log);
  }
  return shader;
}

GLuint link(const Gl_functions& gl, const char* vertex_source, const char* fragment_source) {
  const GLuint vertex = compile(gl, GL_VERTEX_SHADER, vertex_source);
  const GLuint fragment = compile(gl, GL_FRAGMENT_SHADER, fragment_source);
  const GLuint program = gl.CreateProgram();
  gl.AttachShader(program, vertex);
  gl.AttachShader(program, fragment);
  gl.LinkProgram(program);
  gl.DeleteShader(vertex);
  gl.DeleteShader(fragment);
  GLint ok = 0;
  gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[1024] = {};
    gl.GetProgramInfoLog(program, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("shader linking failed: ") + log);
  }
  return program;
}

void attribute(const Gl_functions& gl, GLuint index, int size, int stride_floats, int offset) {
  gl.EnableVertexAttribArray(index);
  gl.VertexAttribPointer(index, size, GL_FLOAT, GL_FALSE, GLsizei(stride_floats * sizeof(float)),
                         reinterpret_cast<const void*>(std::size_t(offset) * sizeof(float)));
}

// Overlay vertices: x, y in pixels, then r, g, b.
class Overlay_builder {
 public:
  void quad(float x0, float y0, float x1, float y1, const std::array<float, 3>& top,
            const std::array<float, 3>& bottom) {
    vertex(x0, y0, top), vertex(x1, y0, top), vertex(x1, y1, bottom);
    vertex(x0, y0, top), vertex(x1, y1, bottom), vertex(x0, y1, bottom);
  }
  // stb_easy_font's glyphs, `scale` times their 7-pixel height; one line per '\n'.
  void text(float x, float y, const std::string& text, float scale) {
    std::istringstream lines(text);
    std::string line;
    for (; std::getline(lines, line); y += 12 * scale) {
      std::vector<char> quads(line.size() * 270 + 1000);  // stb_easy_font's worst case per char
      const int count =
          stb_easy_font_print(0, 0, line.data(), nullptr, quads.data(), int(quads.size()));
      const float* v = reinterpret_cast<const float*>(quads.data());
      for (int q = 0; q < count; ++q, v += 16) {  // 4 vertices of 16 bytes each
        const float qx0 = x + scale * v[0], qy0 = y + scale * v[1];
        const float qx1 = x + scale * v[8], qy1 = y + scale * v[9];
        quad(qx0, qy0, qx1, qy1, kText, kText);
      }
    }
  }
  const std::vector<float>& data() const { return m_data; }

 private:
  static constexpr std::array<float, 3> kText = {0.1f, 0.1f, 0.1f};
  void vertex(float x, float y, const std::array<float, 3>& c) {
    m_data.insert(m_data.end(), {x, y, c[0], c[1], c[2]});
  }
  std::vector<float> m_data;
};

std::string format_value(double value, const std::string& unit) {
  char text[64];
  std::snprintf(text, sizeof text, "%.3g%s", value, unit.c_str());
  return text;
}

}  // namespace

std::string mesh_caption(const std::string& title, std::size_t faces, std::size_t vertices) {
  return title + "\n" + std::to_string(faces) + " faces, " + std::to_string(vertices) + " vertices";
}

Scene_renderer::Scene_renderer(const Gl_functions& gl) : m_gl(gl) {
  m_mesh_program = link(gl, kMeshVertexShader, kMeshFragmentShader);
  m_overlay_program = link(gl, kOverlayVertexShader, kOverlayFragmentShader);
  for (Gpu_mesh& mesh : m_meshes) {
    gl.GenVertexArrays(1, &mesh.vertex_array);
    gl.GenBuffers(1, &mesh.vertex_buffer);
    gl.GenBuffers(1, &mesh.index_buffer);
    gl.BindVertexArray(mesh.vertex_array);
    gl.BindBuffer(GL_ARRAY_BUFFER, mesh.vertex_buffer);
    gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, mesh.index_buffer);
    attribute(gl, 0, 3, Render_mesh::kFloatsPerVertex, 0);
    attribute(gl, 1, 3, Render_mesh::kFloatsPerVertex, 3);
    attribute(gl, 2, 3, Render_mesh::kFloatsPerVertex, 6);
    attribute(gl, 3, 2, Render_mesh::kFloatsPerVertex, 9);
    gl.GenTextures(1, &mesh.texture);
  }
  gl.GenVertexArrays(1, &m_overlay_array);
  gl.GenBuffers(1, &m_overlay_buffer);
  gl.BindVertexArray(m_overlay_array);
  gl.BindBuffer(GL_ARRAY_BUFFER, m_overlay_buffer);
  attribute(gl, 0, 2, 5, 0);
  attribute(gl, 1, 3, 5, 2);
  gl.BindVertexArray(0);
}

Scene_renderer::~Scene_renderer() {
  for (Gpu_mesh& mesh : m_meshes) {
    m_gl.DeleteBuffers(1, &mesh.vertex_buffer);
    m_gl.DeleteBuffers(1, &mesh.index_buffer);
    m_gl.DeleteVertexArrays(1, &mesh.vertex_array);
    m_gl.DeleteTextures(1, &mesh.texture);
  }
  m_gl.DeleteBuffers(1, &m_overlay_buffer);
  m_gl.DeleteVertexArrays(1, &m_overlay_array);
  m_gl.DeleteProgram(m_mesh_program);
  m_gl.DeleteProgram(m_overlay_program);
}

void Scene_renderer::set_mesh(Pane pane, const Render_mesh& mesh) {
  Gpu_mesh& gpu = m_meshes[pane];
  m_gl.BindVertexArray(gpu.vertex_array);  // binds the index buffer, not the vertex buffer
  m_gl.BindBuffer(GL_ARRAY_BUFFER, gpu.vertex_buffer);
  m_gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.vertices.size() * sizeof(float)),
                  mesh.vertices.data(), GL_DYNAMIC_DRAW);
  m_gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * sizeof(std::uint32_t)),
                  mesh.indices.data(), GL_DYNAMIC_DRAW);
  m_gl.BindVertexArray(0);
  gpu.index_count = GLsizei(mesh.indices.size());
}

void Scene_renderer::set_texture(Pane pane, const Texture_image* image) {
  Gpu_mesh& gpu = m_meshes[pane];
  gpu.textured = image != nullptr;
  if (!image) return;
  m_gl.BindTexture(GL_TEXTURE_2D, gpu.texture);
  m_gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);  // RGB rows need not be 4-byte aligned
  m_gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, image->width, image->height, 0, GL_RGB,
                  GL_UNSIGNED_BYTE, image->rgb.data());
  m_gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  m_gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  m_gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  m_gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  m_gl.BindTexture(GL_TEXTURE_2D, 0);
}

void Scene_renderer::draw(int width, int height, const Orbit_camera& camera,
                          const View_options& options, const Scene_captions& captions,
                          int scene_left) {
  m_gl.Viewport(0, 0, width, height);
  m_gl.ClearColor(kBackground[0] / 255.0f, kBackground[1] / 255.0f, kBackground[2] / 255.0f, 1);
  m_gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const int x0 = std::clamp(scene_left, 0, width);
  const int pane_width = (width - x0) / 2;
  const Eigen::Matrix4f projection =
      Orbit_camera::projection(float(pane_width) / float(std::max(height, 1)));
  for (int pane = 0; pane < 2; ++pane) {
    m_gl.Viewport(x0 + pane * pane_width, 0, pane_width, height);
    draw_mesh(m_meshes[pane], camera.view(), projection, options);
  }
  m_gl.Viewport(0, 0, width, height);
  draw_overlay(width, height, x0, captions);
}

void Scene_renderer::draw_mesh(const Gpu_mesh& mesh, const Eigen::Matrix4f& model_view,
                               const Eigen::Matrix4f& projection, const View_options& options) {
  if (mesh.index_count == 0) return;
  m_gl.Enable(GL_DEPTH_TEST);
  m_gl.UseProgram(m_mesh_program);
  m_gl.UniformMatrix4fv(m_gl.GetUniformLocation(m_mesh_program, "model_view"), 1, GL_FALSE,
                        model_view.data());
  m_gl.UniformMatrix4fv(m_gl.GetUniformLocation(m_mesh_program, "projection"), 1, GL_FALSE,
                        projection.data());
  m_gl.Uniform1i(m_gl.GetUniformLocation(m_mesh_program, "flat_shading"), options.flat_shading);
  const GLint solid = m_gl.GetUniformLocation(m_mesh_program, "solid");
  m_gl.Uniform1i(m_gl.GetUniformLocation(m_mesh_program, "textured"), mesh.textured);
  m_gl.Uniform1i(m_gl.GetUniformLocation(m_mesh_program, "texture_map"), 0);
  m_gl.ActiveTexture(GL_TEXTURE0);
  m_gl.BindTexture(GL_TEXTURE_2D, mesh.textured ? mesh.texture : 0);
  m_gl.BindVertexArray(mesh.vertex_array);
  // The wireframe is drawn over the faces, which are pushed back a little so the lines win.
  m_gl.Enable(GL_POLYGON_OFFSET_FILL);
  m_gl.PolygonOffset(1, 1);
  m_gl.Uniform1i(solid, 0);
  m_gl.DrawElements(GL_TRIANGLES, mesh.index_count, GL_UNSIGNED_INT, nullptr);
  m_gl.Disable(GL_POLYGON_OFFSET_FILL);
  if (options.wireframe) {
    m_gl.Uniform1i(solid, 1);
    m_gl.Uniform3f(m_gl.GetUniformLocation(m_mesh_program, "solid_color"), 0.15f, 0.15f, 0.2f);
    m_gl.PolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    m_gl.DrawElements(GL_TRIANGLES, mesh.index_count, GL_UNSIGNED_INT, nullptr);
    m_gl.PolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  }
  m_gl.BindVertexArray(0);
  m_gl.BindTexture(GL_TEXTURE_2D, 0);
  m_gl.Disable(GL_DEPTH_TEST);
}

void Scene_renderer::draw_overlay(int width, int height, int scene_left,
                                  const Scene_captions& captions) {
  const float scale = height >= 480 ? 2.0f : 1.0f;
  Overlay_builder overlay;
  overlay.text(float(scene_left) + 10, 10, captions.left, scale);
  overlay.text(float(scene_left + (width - scene_left) / 2) + 10, 10, captions.right, scale);
  if (captions.legend_max >= 0) {
    // A vertical bar at the right edge, the top value above it and 0 below it.
    const float x1 = float(width) - 12 * scale, x0 = x1 - 8 * scale;
    const float y0 = float(height) * 0.25f, y1 = float(height) * 0.75f;
    constexpr int kBands = 16;
    for (int i = 0; i < kBands; ++i) {
      const float ya = y0 + (y1 - y0) * float(i) / kBands,
                  yb = y0 + (y1 - y0) * float(i + 1) / kBands;
      overlay.quad(x0, ya, x1, yb, heat_color(1 - double(i) / kBands),
                   heat_color(1 - double(i + 1) / kBands));
    }
    const std::string top = format_value(captions.legend_max, captions.legend_unit);
    const float text_width = float(stb_easy_font_width(const_cast<char*>(top.c_str()))) * scale;
    overlay.text(x1 - text_width, y0 - 14 * scale, top, scale);
    overlay.text(x1 - 6 * scale, y1 + 4 * scale, "0", scale);
  }
  if (overlay.data().empty()) return;
  m_gl.UseProgram(m_overlay_program);
  m_gl.Uniform2f(m_gl.GetUniformLocation(m_overlay_program, "viewport"), float(width),
                 float(height));
  m_gl.BindVertexArray(m_overlay_array);
  m_gl.BindBuffer(GL_ARRAY_BUFFER, m_overlay_buffer);
  m_gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(overlay.data().size() * sizeof(float)),
                  overlay.data().data(), GL_STREAM_DRAW);
  m_gl.DrawArrays(GL_TRIANGLES, 0, GLsizei(overlay.data().size() / 5));
  m_gl.BindVertexArray(0);
}

}  // namespace apps
