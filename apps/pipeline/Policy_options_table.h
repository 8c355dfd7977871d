// Binds a policy's command-line options to the fields of its options struct in the library (one
// member of cgal_policies::Simplification_options), so that the defaults come from the library and
// every value is checked against its range before any input is read.
#ifndef CGAL_POLICIES_APPS_PIPELINE_POLICY_OPTIONS_TABLE_H
#define CGAL_POLICIES_APPS_PIPELINE_POLICY_OPTIONS_TABLE_H

#include "policy_registry.h"

#include <cgal_policies/Quadric_options.h>
#include <cgal_policies/Simplification_options.h>

#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace apps {

template <typename Options>
class Policy_options_table {
 public:
  using All_options = cgal_policies::Simplification_options;
  static constexpr double unbounded = std::numeric_limits<double>::infinity();

  // The options of the policy whose struct is `member` of Simplification_options.
  explicit Policy_options_table(Options All_options::*member) : m_member(member) {}

  // --name X, a number in [min, max] (in (min, max] when min_is_excluded).
  Policy_options_table& number(std::string name, double Options::*field, double min, double max,
                               std::string help, bool min_is_excluded = false) {
    Policy_option spec = named(std::move(name), std::move(help));
    spec.default_value = m_defaults.*field;
    spec.min = min;
    spec.max = max;
    spec.min_is_excluded = min_is_excluded;
    const auto member = m_member;
    spec.set = [member, field](All_options& o, double value) { (o.*member).*field = value; };
    spec.get = [member, field](const All_options& o) { return (o.*member).*field; };
    m_options.push_back(std::move(spec));
    return *this;
  }

  // --name N, a whole number in [min, max].
  Policy_options_table& whole_number(std::string name, int Options::*field, int min, int max,
                                     std::string help) {
    Policy_option spec = named(std::move(name), std::move(help));
    spec.default_value = m_defaults.*field;
    spec.min = min;
    spec.max = max;
    spec.is_whole = true;
    const auto member = m_member;
    spec.set = [member, field](All_options& o, double value) { (o.*member).*field = int(value); };
    spec.get = [member, field](const All_options& o) { return double((o.*member).*field); };
    m_options.push_back(std::move(spec));
    return *this;
  }

  // --name alone sets `field` (a member of Options or of a base) to `when_given`; its absence
  // leaves the library's default.
  template <typename Member, typename Value>
  Policy_options_table& flag(std::string name, Member field, Value when_given, std::string help) {
    Policy_option spec = named(std::move(name), std::move(help));
    spec.is_flag = true;
    const auto member = m_member;
    const Options defaults = m_defaults;
    spec.set = [member, field, when_given, defaults](All_options& o, double value) {
      (o.*member).*field = value != 0 ? when_given : defaults.*field;
    };
    spec.get = [member, field, when_given](const All_options& o) {
      return (o.*member).*field == when_given ? 1.0 : 0.0;
    };
    m_options.push_back(std::move(spec));
    return *this;
  }

  // The options of the shared quadric core (cgal_policies::Quadric_options), as every quadric
  // policy of the registry spells them.
  Policy_options_table& border_weight() {
    return number("border-weight", &Options::border_weight, 0, unbounded,
                  "weight of the border planes");
  }
  Policy_options_table& area_weights() {
    return flag("area-weights", &Options::face_weighting, cgal_policies::Face_weighting::area,
                "weight face planes by area");
  }

  const std::vector<Policy_option>& options() const { return m_options; }

 private:
  static Policy_option named(std::string name, std::string help) {
    Policy_option spec;
    spec.name = std::move(name);
    spec.help = std::move(help);
    return spec;
  }

  Options All_options::*m_member;
  Options m_defaults = All_options().*m_member;
  std::vector<Policy_option> m_options;
};

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_PIPELINE_POLICY_OPTIONS_TABLE_H
