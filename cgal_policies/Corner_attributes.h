// Attributes on the corners of a CGAL::Surface_mesh, and the read-only facts about them: seam
// edges, texture areas, the texture's extent. The corner of face(h) at target(h) is the
// halfedge h, so texture coordinates, normals and colours are halfedge property maps, and a vertex
// whose corners disagree lies on a seam. A second set of texture coordinates (glTF's TEXCOORD_1,
// often a lightmap's) is carried as the first is; the texture areas and extent are the first set's.
// A corner's skin influences (glTF's JOINTS_0 and WEIGHTS_0: up to four joints of one skin and
// their weights) are carried too; a corner without them has NaN weights.
// A face's material is a face property map (an index into the material names that the file kept). A
// corner without a value holds NaN; a face without a material, kNoMaterial.
#ifndef CGAL_POLICIES_CORNER_ATTRIBUTES_H
#define CGAL_POLICIES_CORNER_ATTRIBUTES_H

#include <cgal_policies/internal/cgal_version.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace cgal_policies {

template <class Point>
class Corner_attributes {
 public:
  using Mesh = CGAL::Surface_mesh<Point>;
  using Vector = typename CGAL::Kernel_traits<Point>::Kernel::Vector_3;
  using Uv = std::array<double, 2>;
  using Uv_map = typename Mesh::template Property_map<typename Mesh::Halfedge_index, Uv>;
  using Normal_map = typename Mesh::template Property_map<typename Mesh::Halfedge_index, Vector>;
  using Color = std::array<double, 4>;  // red, green, blue and alpha, each in [0, 1]
  using Color_map = typename Mesh::template Property_map<typename Mesh::Halfedge_index, Color>;
  using Material_map =
      typename Mesh::template Property_map<typename Mesh::Face_index, std::uint32_t>;

  // Up to four joints (indices into a skin's joint list) and their weights, which sum to 1; the
  // heaviest first, ties by the lower joint, and an unused slot is joint 0 with weight 0, so that
  // equal influences are equal arrays. None: NaN weights.
  struct Skin_influences {
    std::array<std::uint16_t, 4> joints;
    std::array<double, 4> weights;
  };
  using Skin_map =
      typename Mesh::template Property_map<typename Mesh::Halfedge_index, Skin_influences>;

  static constexpr std::uint32_t kNoMaterial = std::numeric_limits<std::uint32_t>::max();
  static constexpr double kNone = std::numeric_limits<double>::quiet_NaN();

  // Which maps a mesh has, or is to have.
  struct Kinds {
    bool uvs = false, normals = false, colors = false, materials = false, second_uvs = false,
         skins = false;
  };

  // The values of one corner; those the mesh has no map for, or that the corner lacks, are NaN.
  struct Values {
    Uv uv;
    Vector normal;
    Color color;
    Uv second_uv;
    Skin_influences skin;
  };

  // The maps `mesh` already has.
  explicit Corner_attributes(const Mesh& mesh)
      : uvs(find<typename Mesh::Halfedge_index, Uv>(mesh, kUvName)),
        normals(find<typename Mesh::Halfedge_index, Vector>(mesh, kNormalName)),
        colors(find<typename Mesh::Halfedge_index, Color>(mesh, kColorName)),
        materials(find<typename Mesh::Face_index, std::uint32_t>(mesh, kMaterialName)),
        second_uvs(find<typename Mesh::Halfedge_index, Uv>(mesh, kSecondUvName)),
        skins(find<typename Mesh::Halfedge_index, Skin_influences>(mesh, kSkinName)) {}

  // Adds the maps asked for (and keeps those `mesh` has), every value none.
  static Corner_attributes add(Mesh& mesh, const Kinds& kinds) {
    const Values none = no_values();
    if (kinds.uvs)
      mesh.template add_property_map<typename Mesh::Halfedge_index, Uv>(kUvName, none.uv);
    if (kinds.normals)
      mesh.template add_property_map<typename Mesh::Halfedge_index, Vector>(kNormalName,
                                                                            none.normal);
    if (kinds.colors)
      mesh.template add_property_map<typename Mesh::Halfedge_index, Color>(kColorName, none.color);
    if (kinds.materials)
      mesh.template add_property_map<typename Mesh::Face_index, std::uint32_t>(kMaterialName,
                                                                               kNoMaterial);
    if (kinds.second_uvs)
      mesh.template add_property_map<typename Mesh::Halfedge_index, Uv>(kSecondUvName,
                                                                        none.second_uv);
    if (kinds.skins)
      mesh.template add_property_map<typename Mesh::Halfedge_index, Skin_influences>(kSkinName,
                                                                                     none.skin);
    return Corner_attributes(mesh);
  }

  Kinds kinds() const {
    return {uvs.has_value(),       normals.has_value(),    colors.has_value(),
            materials.has_value(), second_uvs.has_value(), skins.has_value()};
  }

  static Values no_values() {
    return {{kNone, kNone},
            Vector(kNone, kNone, kNone),
            {kNone, kNone, kNone, kNone},
            {kNone, kNone},
            {{0, 0, 0, 0}, {kNone, kNone, kNone, kNone}}};
  }

  Values values(typename Mesh::Halfedge_index h) const {
    Values v = no_values();
    if (uvs) v.uv = (*uvs)[h];
    if (normals) v.normal = (*normals)[h];
    if (colors) v.color = (*colors)[h];
    if (second_uvs) v.second_uv = (*second_uvs)[h];
    if (skins) v.skin = (*skins)[h];
    return v;
  }

  // Writes the values of the maps the mesh has.
  void set_values(typename Mesh::Halfedge_index h, const Values& v) const {
    if (uvs) (*uvs)[h] = v.uv;
    if (normals) (*normals)[h] = v.normal;
    if (colors) (*colors)[h] = v.color;
    if (second_uvs) (*second_uvs)[h] = v.second_uv;
    if (skins) (*skins)[h] = v.skin;
  }

  // The values at barycentric weights w of a triangle whose corners hold `corner`: texture
  // coordinates (both sets) and colours blend linearly, normals blend and are made unit again.
  // Colours are clamped to [0, 1], which rounding can overstep (the fuzzer found 1 + 2^-52). Skin
  // influences blend as blend_skins says.
  static Values blend(const std::array<Values, 3>& corner, const std::array<double, 3>& w) {
    Values v{{0, 0},
             Vector(0, 0, 0),
             {0, 0, 0, 0},
             {0, 0},
             blend_skins({corner[0].skin, corner[1].skin, corner[2].skin}, w)};
    for (int k = 0; k < 3; ++k) {
      for (int d = 0; d < 2; ++d) v.uv[d] += w[k] * corner[k].uv[d];
      for (int d = 0; d < 2; ++d) v.second_uv[d] += w[k] * corner[k].second_uv[d];
      v.normal = v.normal + w[k] * corner[k].normal;
      for (int d = 0; d < 4; ++d) v.color[d] += w[k] * corner[k].color[d];
    }
    const double length = std::sqrt(v.normal.squared_length());
    if (length > 0) v.normal = v.normal / length;
    for (double& channel : v.color) channel = std::clamp(channel, 0.0, 1.0);  // NaN stays NaN
    return v;
  }

  // The influences at barycentric weights w: each joint's weight is the w-weighted sum of its
  // weights at the corners (a joint a corner lacks weighs 0 there); the four heaviest are kept
  // (ties: the lower joint) and renormalised to sum 1. None when any corner has none.
  static Skin_influences blend_skins(const std::array<Skin_influences, 3>& corner,
                                     const std::array<double, 3>& w) {
    std::vector<std::pair<std::uint16_t, double>> influences;
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 4; ++i) {
        if (std::isnan(corner[k].weights[i])) return no_values().skin;
        if (corner[k].weights[i] != 0)
          influences.emplace_back(corner[k].joints[i], w[k] * corner[k].weights[i]);
      }
    return normalized_skin(std::move(influences));
  }

  // Joints and their weights as Skin_influences: the weights of a joint named more than once
  // summed, then the four heaviest joints that weigh more than 0 (ties: the lower joint),
  // renormalised to sum 1; none when none weighs more than 0.
  static Skin_influences normalized_skin(std::vector<std::pair<std::uint16_t, double>> influences) {
    std::sort(influences.begin(), influences.end());
    std::vector<std::pair<std::uint16_t, double>> merged;
    for (const auto& [joint, weight] : influences)
      if (!merged.empty() && merged.back().first == joint)
        merged.back().second += weight;
      else
        merged.emplace_back(joint, weight);
    influences.clear();
    for (const auto& influence : merged)
      if (influence.second > 0) influences.push_back(influence);
    std::stable_sort(influences.begin(), influences.end(), [](const auto& a, const auto& b) {
      return a.second != b.second ? a.second > b.second : a.first < b.first;
    });
    influences.resize(std::min<std::size_t>(influences.size(), 4));
    double total = 0;
    for (const auto& i : influences) total += i.second;
    if (!(total > 0)) return no_values().skin;
    Skin_influences skin{{0, 0, 0, 0}, {0, 0, 0, 0}};
    for (std::size_t i = 0; i < influences.size(); ++i) {
      skin.joints[i] = influences[i].first;
      skin.weights[i] = influences[i].second / total;
    }
    return skin;
  }

  static bool same_values(const Values& a, const Values& b) {
    for (int d = 0; d < 2; ++d)
      if (!same_number(a.uv[d], b.uv[d])) return false;
    for (int d = 0; d < 3; ++d)
      if (!same_number(a.normal[d], b.normal[d])) return false;
    for (int d = 0; d < 4; ++d)
      if (!same_number(a.color[d], b.color[d])) return false;
    for (int d = 0; d < 2; ++d)
      if (!same_number(a.second_uv[d], b.second_uv[d])) return false;
    return same_skin(a.skin, b.skin);
  }

  // Removes every map of this kind from `mesh`.
  static void remove(Mesh& mesh) {
    remove_corner_values(mesh);
    Corner_attributes found(mesh);
    if (found.materials) mesh.remove_property_map(*found.materials);
  }

  // Removes the texture coordinates (both sets), normals, colours and skin influences, and keeps
  // the materials.
  static void remove_corner_values(Mesh& mesh) {
    Corner_attributes found(mesh);
    if (found.uvs) mesh.remove_property_map(*found.uvs);
    if (found.normals) mesh.remove_property_map(*found.normals);
    if (found.colors) mesh.remove_property_map(*found.colors);
    if (found.second_uvs) mesh.remove_property_map(*found.second_uvs);
    if (found.skins) mesh.remove_property_map(*found.skins);
  }

  bool any() const { return any_corner_values() || materials; }
  bool any_corner_values() const { return uvs || normals || colors || second_uvs || skins; }

  // Whether the values on the two sides of the edge of `h` differ at either end (in any kind of
  // value, either set of texture coordinates included), or it is a border: a seam edge.
  bool is_seam_edge(const Mesh& mesh, typename Mesh::Halfedge_index h) const {
    const auto o = mesh.opposite(h);
    if (mesh.is_border(h) || mesh.is_border(o)) return true;
    return !same_corner_values(h, mesh.prev(o)) || !same_corner_values(mesh.prev(h), o);
  }

  // Twice the signed area of a texture triangle: positive when it turns counterclockwise.
  static double uv_area(const Uv& a, const Uv& b, const Uv& c) {
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  }
  // That of face f's texture triangle; needs the texture coordinate map.
  double face_uv_area(const Mesh& mesh, typename Mesh::Face_index f) const {
    const auto h = mesh.halfedge(f);
    return uv_area((*uvs)[h], (*uvs)[mesh.next(h)], (*uvs)[mesh.prev(h)]);
  }

  // The diagonal of the bounding box of the finite texture coordinates; 0 without any.
  double uv_extent(const Mesh& mesh) const {
    if (!uvs) return 0;
    Uv low{kNone, kNone}, high{kNone, kNone};
    for (auto h : mesh.halfedges()) {
      const Uv& uv = (*uvs)[h];
      if (mesh.is_border(h) || !std::isfinite(uv[0]) || !std::isfinite(uv[1])) continue;
      for (int d = 0; d < 2; ++d) {
        low[d] = std::fmin(low[d], uv[d]);  // fmin and fmax skip the NaN they start from
        high[d] = std::fmax(high[d], uv[d]);
      }
    }
    return std::isfinite(low[0]) ? std::hypot(high[0] - low[0], high[1] - low[1]) : 0;
  }

  std::optional<Uv_map> uvs;
  std::optional<Normal_map> normals;
  std::optional<Color_map> colors;
  std::optional<Material_map> materials;
  std::optional<Uv_map> second_uvs;
  std::optional<Skin_map> skins;

 private:
  static bool same_number(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

  static bool same_skin(const Skin_influences& a, const Skin_influences& b) {
    for (int i = 0; i < 4; ++i)
      if (a.joints[i] != b.joints[i] || !same_number(a.weights[i], b.weights[i])) return false;
    return true;
  }

  // same_values of two corners, reading only the maps the mesh has (the seam test is hot).
  bool same_corner_values(typename Mesh::Halfedge_index a, typename Mesh::Halfedge_index b) const {
    const auto same = [&](const auto& map, int size) {
      if (!map) return true;
      const auto &p = (*map)[a], &q = (*map)[b];
      for (int d = 0; d < size; ++d)
        if (!same_number(p[d], q[d])) return false;
      return true;
    };
    return same(uvs, 2) && same(normals, 3) && same(colors, 4) && same(second_uvs, 2) &&
           (!skins || same_skin((*skins)[a], (*skins)[b]));
  }

  static constexpr const char* kUvName = "h:cgal_policies:uv";
  static constexpr const char* kNormalName = "h:cgal_policies:normal";
  static constexpr const char* kColorName = "h:cgal_policies:color";
  static constexpr const char* kMaterialName = "f:cgal_policies:material";
  static constexpr const char* kSecondUvName = "h:cgal_policies:second_uv";
  static constexpr const char* kSkinName = "h:cgal_policies:skin";

  template <class Index, class Value>
  static std::optional<typename Mesh::template Property_map<Index, Value>> find(const Mesh& mesh,
                                                                                const char* name) {
    return internal::find_property_map<Index, Value>(mesh, name);
  }
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_CORNER_ATTRIBUTES_H
