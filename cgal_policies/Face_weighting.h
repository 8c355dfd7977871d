// How a face's plane quadric is weighted when it is added to its vertices (docs/quadric_core.md).
#ifndef CGAL_POLICIES_FACE_WEIGHTING_H
#define CGAL_POLICIES_FACE_WEIGHTING_H

namespace cgal_policies {

enum class Face_weighting {
  unit,  // every face counts once, as in the papers
  area   // a face counts by its area, so small slivers weigh little
};

}  // namespace cgal_policies

#endif  // CGAL_POLICIES_FACE_WEIGHTING_H
