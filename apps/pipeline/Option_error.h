// A policy option outside its documented range: the message names the option, its range and the
// policy. The command line turns it into exit code 2; the Python module into ValueError.
#ifndef CGAL_POLICIES_APPS_PIPELINE_OPTION_ERROR_H
#define CGAL_POLICIES_APPS_PIPELINE_OPTION_ERROR_H

#include <stdexcept>

namespace apps {

class Option_error : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_PIPELINE_OPTION_ERROR_H
