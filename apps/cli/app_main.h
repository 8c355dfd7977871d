// The outer frame of every app's main(): turns any failure into one line on stderr, "<app>: <file>:
// <cause>", and the exit code of README.md; an interrupt exits 130 or 143 (Removed_on_interrupt).
#ifndef CGAL_POLICIES_APPS_CLI_APP_MAIN_H
#define CGAL_POLICIES_APPS_CLI_APP_MAIN_H

#include "App_error.h"
#include "io/Io_error.h"
#include "io/Removed_on_interrupt.h"
#include "pipeline/Option_error.h"

#include <exception>
#include <functional>
#include <iostream>
#include <new>

namespace apps {

inline int guarded_main(const char* app, const std::function<int()>& body) {
  cgal_policies::io::install_interrupt_handlers(app);
  try {
    return body();
  } catch (const App_error& e) {
    std::cerr << app << ": " << e.what() << '\n';
    return e.code();
  } catch (const cgal_policies::io::Io_error& e) {
    std::cerr << app << ": " << e.what() << '\n';
    return e.kind() == cgal_policies::io::Io_error::Kind::unreadable_input ? exit_bad_input
                                                                           : exit_bad_output;
  } catch (const Option_error& e) {
    std::cerr << app << ": " << e.what() << '\n';
    return exit_usage;
  } catch (const std::bad_alloc&) {
    std::cerr << app << ": out of memory\n";
  } catch (const std::exception& e) {
    std::cerr << app << ": " << e.what() << '\n';
  }
  return exit_not_done;
}

}  // namespace apps

#endif  // CGAL_POLICIES_APPS_CLI_APP_MAIN_H
