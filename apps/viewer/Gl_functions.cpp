#include "Gl_functions.h"

#include <stdexcept>
#include <string>

namespace apps {

Gl_functions::Gl_functions(const Gl_loader& load) {
#define CGAL_POLICIES_VIEWER_GL_LOAD(type, name)   \
  name = reinterpret_cast<type>(load("gl" #name)); \
  if (!name) throw std::runtime_error("OpenGL function gl" #name " is not available");
  CGAL_POLICIES_VIEWER_GL_FUNCTIONS(CGAL_POLICIES_VIEWER_GL_LOAD)
#undef CGAL_POLICIES_VIEWER_GL_LOAD
}

}  // namespace apps
