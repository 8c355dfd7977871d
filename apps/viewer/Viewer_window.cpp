#include "Viewer_window.h"

#include "Collapse_replay.h"
#include "Latest_task.h"
#include "Surface_distance.h"
#include "evaluation/attribute_error.h"
#include "evaluation/mesh_validity.h"
#include "evaluation/surface_error.h"
#include "pipeline/Pipeline.h"
#include "snapshot.h"

#include <cgal_policies/Corner_attributes.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace apps {
namespace {

// What a background run hands back for one policy and its settings.
struct Simplified {
  std::shared_ptr<const Collapse_replay> replay;  // when its collapses were recorded
  Mesh mesh;                                      // otherwise: simplified straight to `target`
  std::size_t target = 0;
  cgal_policies::Simplification_report report;
  std::size_t smallest_faces = 1;  // what the slider may ask for
};

class Viewer {
 public:
  Viewer(const Gl_functions& gl, const std::vector<Mesh>& levels, const Viewer_start& start)
      : m_levels(levels),
        m_title(start.title),
        m_policy(start.policy),
        m_options(start.options),
        m_values(values_of(*start.policy, start.options)),
        m_view(start.view),
        m_heat_map(start.heat_map),
        m_texture(start.texture),
        m_fit(start.options.fit),
        m_renderer(gl) {
    show_level(start.level, start.ratio);
  }

  // One frame's logic: background results, the panel, the mouse, the keys.
  void update() {
    try {
      if (std::optional<Simplified> result = m_simplifier.take()) {
        m_message.clear();
        m_current = std::move(*result);
        m_recording = false;
        m_distance_cache.clear();
        show_simplified();
        if (!m_current->replay && m_current->target != m_target) simplify(false);
      }
      if (std::optional<Mesh_error> error = m_measurer.take()) m_error = *error;
    } catch (const std::exception& e) {
      m_message = e.what();
    }
    panel();
    mouse();
    keys();
  }

  void draw(int width, int height) {
    Scene_captions captions;
    captions.left = mesh_caption(level_title(m_level, m_levels.size()), input_faces(),
                                 level_mesh().number_of_vertices());
    captions.right = mesh_caption(pipeline_name(run_options()), m_faces, m_vertices);
    if (m_heat_map) {
      captions.legend_max = m_legend_max;
      captions.legend_unit = "% diag";
    }
    // The panel is a sidebar: the panes start right of it, so it hides neither mesh.
    const int left = int(m_panel_width * ImGui::GetIO().DisplayFramebufferScale.x);
    m_renderer.draw(width, height, m_camera, m_view, captions, left);
  }

  bool busy() const { return m_simplifier.busy() || m_measurer.busy(); }

 private:
  std::size_t input_faces() const { return m_original.triangles.size(); }

  // Makes level `level` the mesh shown on the left and simplified on the right, the target
  // `ratio` of its faces; the runs and measures under way for another level are dropped.
  void show_level(std::size_t level, double ratio) {
    m_level = level;
    m_original = Indexed_mesh::from_mesh(level_mesh());
    m_frame = Mesh_frame::of(m_original);
    m_corner_values = cgal_policies::Corner_attributes<Point>(level_mesh()).any_corner_values();
    m_target = std::max<std::size_t>(1, std::size_t(std::llround(ratio * double(input_faces()))));
    m_current.reset();
    m_error.reset();
    m_distance.reset();
    m_distance_cache.clear();
    if (!show_corner_values(m_renderer, Scene_renderer::left, level_mesh(), m_frame, m_texture))
      m_renderer.set_mesh(Scene_renderer::left, make_render_mesh(m_original, m_frame));
    simplify(true);
  }

  // The level shown, which the panel simplifies.
  const Mesh& level_mesh() const { return m_levels[m_level]; }

  // Steps `by` levels (negative: finer), within the file's levels, keeping the target's ratio.
  void step_level(int by) {
    const int last = int(m_levels.size()) - 1;
    const auto level = std::size_t(std::clamp(int(m_level) + by, 0, last));
    if (level != m_level) show_level(level, double(m_target) / double(input_faces()));
  }

  // The options of the next run: the panel's policy, its values, the angle and the fit.
  cgal_policies::Simplification_options run_options() const {
    cgal_policies::Simplification_options options = m_options;
    options.policy = m_policy->policy;
    options.fit = m_fit;
    apply_policy_options(*m_policy, m_values, options);
    return options;
  }

  // The values of `policy`'s options in `options`, for the panel to edit.
  static Option_values values_of(const Policy_entry& policy,
                                 const cgal_policies::Simplification_options& options) {
    Option_values values;
    for (const Policy_option& o : policy.options) values[o.name] = o.get(options);
    return values;
  }

  // Runs the pipeline in the background: recording all its collapses, or straight to the target.
  void simplify(bool record) {
    cgal_policies::Simplification_options options = run_options();
    options.progress = [this](cgal_policies::Simplification_pass, double, std::size_t faces) {
      m_progress_faces = faces;
    };
    m_progress_faces = input_faces();
    // A fitted result cannot be replayed collapse by collapse, nor can one that carries the mesh's
    // texture coordinates, normals or colours (a replay has the points only): each target is run
    // anew.
    record = record && !m_fit && !m_corner_values;
    m_recording = record;
    // The job keeps to its level: another may be shown before it ends.
    m_simplifier.submit([input = &level_mesh(), record, options, target = m_target]() mutable {
      Simplified result;
      result.target = target;
      if (record) {
        options.target = cgal_policies::Face_target::faces(0);
        const Collapse_history history = record_collapses(*input, options);
        result.report = history.report;
        result.smallest_faces = std::max<std::size_t>(1, history.final_faces);
        // A policy that simplifies outside the edge-collapse visitor leaves no history.
        if (!history.collapses.empty()) {
          result.replay = std::make_shared<const Collapse_replay>(*input, history);
          return result;
        }
      }
      result.mesh = *input;
      options.target = cgal_policies::Face_target::faces(target);
      result.report = Pipeline(options).run(result.mesh);
      return result;
    });
  }

  // Shows the current result at the current target, and measures it in the background.
  void show_simplified() {
    Indexed_mesh mesh;
    if (m_current->replay) {
      const Collapse_replay& replay = *m_current->replay;
      const std::size_t step = replay.step_for_target(m_target);
      mesh = replay.mesh_after(step);
      m_seconds = replay.seconds_after(step);
    } else {
      mesh = Indexed_mesh::from_mesh(m_current->mesh);
      m_seconds = m_current->report.total_seconds();
      m_distance_cache.clear();  // the vertex indices are the new mesh's own
    }
    m_faces = mesh.triangles.size();
    m_vertices = mesh.vertex_count;
    std::vector<double> errors;
    m_legend_max = 0;
    if (m_heat_map) {
      if (!m_distance) m_distance = std::make_unique<Surface_distance>(level_mesh());
      errors = m_distance->vertex_distances(mesh, m_distance_cache);
      for (double& e : errors) e *= 100 * m_frame.scale;  // percent of the diagonal
      m_legend_max = errors.empty() ? 0 : *std::max_element(errors.begin(), errors.end());
    }
    if (m_heat_map || m_current->replay ||
        !show_corner_values(m_renderer, Scene_renderer::right, m_current->mesh, m_frame, m_texture))
      m_renderer.set_mesh(Scene_renderer::right,
                          make_render_mesh(mesh, m_frame, errors, m_legend_max));
    m_error.reset();
    m_measurer.submit([input = &level_mesh(), mesh = std::move(mesh)] {
      return measure_mesh_error(*input, mesh.to_mesh(), kViewerErrorSamples);
    });
  }

  void panel() {
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImVec2(0, ImGui::GetIO().DisplaySize.y));
    ImGui::Begin("simplification", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize);
    ImGui::PushItemWidth(180);
    ImGui::TextUnformatted(m_title.c_str());
    if (m_levels.size() > 1) level_control();
    bool changed = false;
    if (ImGui::BeginCombo("policy", m_policy->name.c_str())) {
      for (const Policy_entry& entry : policy_registry())
        if (ImGui::Selectable(entry.name.c_str(), &entry == m_policy) && &entry != m_policy) {
          m_policy = &entry;
          m_values = values_of(entry, cgal_policies::Simplification_options());
          changed = true;
        }
      ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", m_policy->summary.c_str());
    for (const Policy_option& option : m_policy->options) {
      double& value = m_values[option.name];
      if (option.is_flag) {
        bool on = value != 0;
        if (ImGui::Checkbox(option.name.c_str(), &on)) {
          value = on ? 1 : 0;
          changed = true;
        }
      } else {
        ImGui::InputDouble(option.name.c_str(), &value, 0, 0, "%.6g");
        if (ImGui::IsItemActivated()) m_value_before_edit = value;
        if (ImGui::IsItemDeactivatedAfterEdit()) {
          try {
            check_option_values(m_policy->name, m_policy->options, {{option.name, value}});
            changed = true;
          } catch (const std::exception& e) {  // out of range: say so, keep the old value
            m_message = e.what();
            value = m_value_before_edit;
          }
        }
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", option.help.c_str());
    }
    ImGui::InputDouble("max normal angle", &m_options.max_normal_angle_deg, 0, 0, "%.4g");
    changed |= ImGui::IsItemDeactivatedAfterEdit();
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("our policies refuse collapses that turn a face normal further (degrees)");
    changed |= ImGui::Checkbox("fit to input", &m_fit);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("then fit the result to the input, both ways (docs/fitting.md)");
    if (changed) simplify(true);

    ImGui::Separator();
    const int smallest = int(m_current ? m_current->smallest_faces : 1);
    int target = int(m_target);
    if (ImGui::SliderInt("target faces", &target, smallest, int(input_faces()), "%d",
                         ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp)) {
      m_target = std::size_t(target);
      if (m_current && m_current->replay)
        show_simplified();
      else if (!m_recording)  // a recording under way will show the new target
        simplify(false);
    }
    ImGui::Text("ratio %.4g", double(m_target) / double(input_faces()));
    ImGui::Checkbox("flat shading", &m_view.flat_shading);
    ImGui::SameLine();
    ImGui::Checkbox("wireframe", &m_view.wireframe);
    if (ImGui::Checkbox("error heat map", &m_heat_map) && m_current) show_simplified();

    ImGui::Separator();
    if (m_simplifier.busy()) {
      const double done =
          1 - double(m_progress_faces) / double(std::max<std::size_t>(1, input_faces()));
      ImGui::ProgressBar(float(done), ImVec2(-1, 0), ("running " + m_policy->name).c_str());
    }
    if (m_current) {
      ImGui::Text("%zu faces, %zu vertices", m_faces, m_vertices);
      ImGui::Text("%.3f s to get here%s", m_seconds,
                  m_current->replay ? " (replayed at once)" : "");
      if (m_error) {
        const double d = m_error->bbox_diagonal;
        ImGui::Text("Hausdorff %.4f%% of the diagonal", 100 * m_error->hausdorff / d);
        ImGui::Text("mean %.4f%% / %.4f%%", 100 * m_error->mean_a_to_b / d,
                    100 * m_error->mean_b_to_a / d);
      } else {
        ImGui::TextUnformatted("measuring the error...");
      }
    }
    if (!m_message.empty())
      ImGui::TextColored(ImVec4(0.8f, 0.1f, 0.1f, 1), "%s", m_message.c_str());
    ImGui::TextDisabled("drag: orbit, right/shift drag: pan, wheel: zoom");
    if (m_levels.size() > 1) ImGui::TextDisabled("PageUp/PageDown or [ ]: finer/coarser level");
    ImGui::PopItemWidth();
    m_panel_width = ImGui::GetWindowWidth();
    ImGui::End();
  }

  // The file's levels of detail: a slider over them and what the level shown holds.
  void level_control() {
    int level = int(m_level);
    if (ImGui::SliderInt("level", &level, 0, int(m_levels.size()) - 1, "%d",
                         ImGuiSliderFlags_AlwaysClamp))
      step_level(level - int(m_level));
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("the file's levels of detail (MSFT_lod), 0 the finest");
    ImGui::Text("%s, %zu faces", level_title(m_level, m_levels.size()).c_str(), input_faces());
    ImGui::Separator();
  }

  // PageUp or '[' shows the next finer level, PageDown or ']' the next coarser one; characters,
  // not keys, for the brackets, which sit on different keys in different layouts.
  void keys() {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantCaptureKeyboard || m_levels.size() < 2) return;
    int by = 0;
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_PageUp))) --by;
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_PageDown))) ++by;
    for (const ImWchar c : io.InputQueueCharacters) by += c == ']' ? 1 : c == '[' ? -1 : 0;
    if (by != 0) step_level(by);
  }

  void mouse() {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantCaptureMouse) return;
    const float height = std::max(1.0f, io.DisplaySize.y);
    const bool pan = ImGui::IsMouseDown(ImGuiMouseButton_Right) ||
                     ImGui::IsMouseDown(ImGuiMouseButton_Middle) ||
                     (ImGui::IsMouseDown(ImGuiMouseButton_Left) && io.KeyShift);
    if (pan)
      m_camera.pan(io.MouseDelta.x / height, io.MouseDelta.y / height);
    else if (ImGui::IsMouseDown(ImGuiMouseButton_Left))
      m_camera.orbit(io.MouseDelta.x * 0.01f, io.MouseDelta.y * 0.01f);
    if (io.MouseWheel != 0) m_camera.zoom(std::pow(0.9f, io.MouseWheel));
  }

  const std::vector<Mesh>& m_levels;  // the file's levels of detail, finest first
  std::size_t m_level = 0;            // the level shown
  Indexed_mesh m_original;            // the same, for the left pane
  Mesh_frame m_frame;                 // the level's own, as a snapshot of it has
  const std::string m_title;
  const Policy_entry* m_policy;
  cgal_policies::Simplification_options m_options;  // but for the policy's option values
  Option_values m_values;                           // the policy's, as the panel edits them
  View_options m_view;
  float m_panel_width = 0;         // in window coordinates, as the last frame laid it out
  double m_value_before_edit = 0;  // of the policy option being edited
  bool m_heat_map;
  const Texture_image* m_texture;  // for the meshes with texture coordinates; may be none
  bool m_corner_values = false;    // the level has texture coordinates, normals or colours
  bool m_fit;                      // the fitting pass after the policy (docs/fitting.md)
  Scene_renderer m_renderer;
  Orbit_camera m_camera;
  std::size_t m_target = 1;
  std::optional<Simplified> m_current;
  bool m_recording = false;  // the latest background run records collapses
  std::size_t m_faces = 0, m_vertices = 0;
  double m_seconds = 0, m_legend_max = 0;
  std::optional<Mesh_error> m_error;
  std::unique_ptr<Surface_distance> m_distance;  // built when the heat map is first asked for
  std::vector<double> m_distance_cache;
  std::string m_message;
  std::atomic<std::size_t> m_progress_faces{0};
  // Last: their threads use the members above and are joined first.
  Latest_task<Simplified> m_simplifier;
  Latest_task<Mesh_error> m_measurer;
};

}  // namespace

void run_viewer_window(const std::vector<Mesh>& levels, const Viewer_start& start) {
  if (!glfwInit()) throw std::runtime_error("cannot open a window (no display?); try --snapshot");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  GLFWwindow* window =
      glfwCreateWindow(1400, 760, ("mesh_viewer - " + start.title).c_str(), nullptr, nullptr);
  if (!window) {
    glfwTerminate();
    throw std::runtime_error("cannot create an OpenGL 3.3 core window");
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // leave no imgui.ini behind
  ImGui::StyleColorsLight();
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
  {
    const Gl_functions gl([](const char* name) { return Gl_proc(glfwGetProcAddress(name)); });
    Viewer viewer(gl, levels, start);
    while (!glfwWindowShouldClose(window)) {
      // Idle without spinning: the machine is shared and the picture only changes on events.
      glfwWaitEventsTimeout(viewer.busy() ? 0.05 : 0.5);
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();
      viewer.update();
      ImGui::Render();
      int width = 0, height = 0;
      glfwGetFramebufferSize(window, &width, &height);
      viewer.draw(width, height);
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      glfwSwapBuffers(window);
    }
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
}

}  // namespace apps
