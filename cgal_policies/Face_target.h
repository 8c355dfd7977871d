// Face_target: how many faces a simplification keeps, given as a ratio of the input's faces or as a
// count, resolved once the input is known.
//   Face_target::ratio(r)   keep round(r * input faces), 0 < r <= 1
//   Face_target::faces(n)   keep n faces (0: as few as the policy can)
// Usage:
//   const std::size_t target = cgal_policies::Face_target::ratio(0.1).of(mesh.number_of_faces());
#ifndef CGAL_POLICIES_FACE_TARGET_H
#define CGAL_POLICIES_FACE_TARGET_H

#include <CGAL/assertions.h>

#include <cmath>
#include <cstddef>

namespace cgal_policies {

class Face_target {
 public:
  static Face_target ratio(double r) {
    CGAL_precondition(r > 0 && r <= 1);
    return Face_target(r, 0);
  }
  static Face_target faces(std::size_t n) { return Face_target(0, n); }

  std::size_t of(std::size_t input_faces) const {
    return is_ratio() ? std::size_t(std::llround(m_ratio * double(input_faces))) : m_faces;
  }
  bool is_ratio() const { return m_ratio > 0; }
  double ratio_value() const { return m_ratio; }
  std::size_t face_count() const { return m_faces; }

 private:
  Face_target(double r, std::size_t n) : m_ratio(r), m_faces(n) {}

  double m_ratio;       // 0 for a face count
  std::size_t m_faces;  // 0 for a ratio
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_FACE_TARGET_H
