// One function per source file of policies, each describing the policies it instantiates.
#ifndef CGAL_POLICIES_APPS_PIPELINE_POLICY_ENTRIES_H
#define CGAL_POLICIES_APPS_PIPELINE_POLICY_ENTRIES_H

#include "policy_registry.h"

#include <vector>

namespace apps {

std::vector<Policy_entry> cgal_baseline_policies();  // policies_cgal.cpp: gh, gh-prob, lt
std::vector<Policy_entry> classic_policies();        // policies_classic.cpp: classic
std::vector<Policy_entry> curvature_policies();      // policies_curvature.cpp: curvature
std::vector<Policy_entry> fusion_policies();         // policies_fusion.cpp: fusion
std::vector<Policy_entry> fast_policies();           // policies_fast.cpp: fast, flat-lt
std::vector<Policy_entry> hausdorff_policies();      // policies_hausdorff.cpp: hausdorff
std::vector<Policy_entry> attribute_policies();      // policies_attributes.cpp: attributes

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_PIPELINE_POLICY_ENTRIES_H
