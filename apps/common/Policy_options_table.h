// Binds a policy's command-line options to the fields of its options struct in the library, so
// that the defaults come from the library, every value is checked against its range before any
// input is read, and the policy receives a typed struct.
#ifndef CGAL_POLICIES_APPS_POLICY_OPTIONS_TABLE_H
#define CGAL_POLICIES_APPS_POLICY_OPTIONS_TABLE_H

#include "policy_registry.h"

#include <cgal_policies/Quadric_options.h>

#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace apps {

template <typename Options>
class Policy_options_table {
 public:
  static constexpr double unbounded = std::numeric_limits<double>::infinity();

  // --name X, a number in [min, max] (in (min, max] when min_is_excluded).
  Policy_options_table& number(std::string name, double Options::*field, double min, double max,
                               std::string help, bool min_is_excluded = false) {
    Policy_option spec = named(std::move(name), std::move(help));
    spec.default_value = m_defaults.*field;
    spec.min = min;
    spec.max = max;
    spec.min_is_excluded = min_is_excluded;
    return add(std::move(spec), [field](Options& o, double value) { o.*field = value; });
  }

  // --name N, a whole number in [min, max].
  Policy_options_table& whole_number(std::string name, int Options::*field, int min, int max,
                                     std::string help) {
    Policy_option spec = named(std::move(name), std::move(help));
    spec.default_value = m_defaults.*field;
    spec.min = min;
    spec.max = max;
    spec.is_whole = true;
    return add(std::move(spec), [field](Options& o, double value) { o.*field = int(value); });
  }

  // --name alone sets `field` (a member of Options or of a base) to `when_given`; its absence
  // leaves the library's default.
  template <typename Member, typename Value>
  Policy_options_table& flag(std::string name, Member field, Value when_given, std::string help) {
    Policy_option spec = named(std::move(name), std::move(help));
    spec.is_flag = true;
    return add(std::move(spec), [field, when_given](Options& o, double value) {
      if (value != 0) o.*field = when_given;
    });
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

  // The struct for values already checked by check_policy_options; absent names keep defaults.
  Options read(const Option_values& values) const {
    Options options = m_defaults;
    for (std::size_t i = 0; i < m_options.size(); ++i) {
      const auto it = values.find(m_options[i].name);
      if (it != values.end()) m_setters[i](options, it->second);
    }
    return options;
  }

 private:
  static Policy_option named(std::string name, std::string help) {
    Policy_option spec;
    spec.name = std::move(name);
    spec.help = std::move(help);
    return spec;
  }

  Policy_options_table& add(Policy_option spec, std::function<void(Options&, double)> setter) {
    m_options.push_back(std::move(spec));
    m_setters.push_back(std::move(setter));
    return *this;
  }

  Options m_defaults{};
  std::vector<Policy_option> m_options;
  std::vector<std::function<void(Options&, double)>> m_setters;
};

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_POLICY_OPTIONS_TABLE_H
