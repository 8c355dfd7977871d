// The corner values of a streamed source's triangles (the concept is in Streamed_cut.h), and their
// record in the spill files: the doubles of the kinds the source has, corner after corner, after
// the triangle's material.
#ifndef CGAL_POLICIES_INTERNAL_STREAMED_CORNERS_H
#define CGAL_POLICIES_INTERNAL_STREAMED_CORNERS_H

#include <cgal_policies/Corner_attributes.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

namespace cgal_policies {
namespace internal {

// What a triangle of a source with corner values carries besides its points: its corners' values,
// in the order of its points (NaN where a corner has none), and its material (kNoMaterial: none).
template <class Point>
struct Streamed_corners {
  std::array<typename Corner_attributes<Point>::Values, 3> values;
  std::uint32_t material = Corner_attributes<Point>::kNoMaterial;
};

template <class Source, class = void>
struct Has_corner_kinds : std::false_type {};
template <class Source>
struct Has_corner_kinds<Source, std::void_t<decltype(std::declval<const Source&>().corner_kinds())>>
    : std::true_type {};

// The kinds of values the source's corners carry: its corner_kinds() after its pass over the
// points, or none for a source without that member.
template <class Point, class Source>
typename Corner_attributes<Point>::Kinds corner_kinds_of(const Source& source) {
  if constexpr (Has_corner_kinds<Source>::value)
    return source.corner_kinds();
  else
    return {};
}

// The doubles of one triangle's record.
template <class Point>
std::size_t streamed_corner_doubles(const typename Corner_attributes<Point>::Kinds& kinds) {
  const std::size_t corner = (kinds.uvs ? 2 : 0) + (kinds.normals ? 3 : 0) +
                             (kinds.colors ? 4 : 0) + (kinds.second_uvs ? 2 : 0) +
                             (kinds.skins ? 8 : 0);
  return (kinds.materials ? 1 : 0) + 3 * corner;
}

// Calls f(double&) on each double of the record of `corners` in its order, then stores them back:
// the one layout that encoding and decoding share.
template <class Point, class F>
void for_each_streamed_double(const typename Corner_attributes<Point>::Kinds& kinds,
                              Streamed_corners<Point>& corners, F f) {
  using Vector = typename Corner_attributes<Point>::Vector;
  double material = corners.material;
  if (kinds.materials) f(material);
  corners.material = std::uint32_t(material);
  for (auto& v : corners.values) {
    if (kinds.uvs)
      for (double& x : v.uv) f(x);
    if (kinds.normals) {  // a CGAL vector has no setters
      std::array<double, 3> n = {v.normal.x(), v.normal.y(), v.normal.z()};
      for (double& x : n) f(x);
      v.normal = Vector(n[0], n[1], n[2]);
    }
    if (kinds.colors)
      for (double& x : v.color) f(x);
    if (kinds.second_uvs)
      for (double& x : v.second_uv) f(x);
    if (kinds.skins)
      for (std::size_t k = 0; k < 4; ++k) {
        double joint = v.skin.joints[k];
        f(joint);
        v.skin.joints[k] = std::uint16_t(joint);
        f(v.skin.weights[k]);
      }
  }
}

template <class Point>
void encode_streamed_corners(const typename Corner_attributes<Point>::Kinds& kinds,
                             Streamed_corners<Point> corners, double* out) {
  for_each_streamed_double<Point>(kinds, corners, [&out](double& x) { *out++ = x; });
}

template <class Point>
Streamed_corners<Point> decode_streamed_corners(
    const typename Corner_attributes<Point>::Kinds& kinds, const double* in) {
  Streamed_corners<Point> corners;
  corners.values.fill(Corner_attributes<Point>::no_values());
  for_each_streamed_double<Point>(kinds, corners, [&in](double& x) { x = *in++; });
  return corners;
}

}  // namespace internal
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_INTERNAL_STREAMED_CORNERS_H
