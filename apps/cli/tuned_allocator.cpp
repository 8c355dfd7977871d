#include "tuned_allocator.h"

#include <cstdlib>
#include <cstring>

#include <unistd.h>

namespace apps {
namespace {

// hugetlb=1: madvise(MADV_HUGEPAGE) on what malloc maps. The heap grows by 64 MiB at a time and
// keeps up to 4 GiB free at its top; blocks up to 32 MiB come from it rather than from mappings of
// their own, which would be unmapped when freed.
constexpr const char* kTunables =
    "glibc.malloc.hugetlb=1:glibc.malloc.top_pad=67108864:"
    "glibc.malloc.trim_threshold=4294967296:glibc.malloc.mmap_threshold=33554432";

}  // namespace

std::optional<std::string> tuned_allocator_tunables(const char* current) {
  if (current == nullptr || *current == '\0') return std::string(kTunables);
  if (std::strstr(current, "glibc.malloc.") != nullptr) return std::nullopt;
  return std::string(current) + ":" + kTunables;
}

void restart_with_tuned_allocator(char** argv) {
#ifdef __GLIBC__
  const char* preload = std::getenv("LD_PRELOAD");
  if (preload != nullptr && std::strstr(preload, "vgpreload") != nullptr) return;
  const std::optional<std::string> tunables =
      tuned_allocator_tunables(std::getenv("GLIBC_TUNABLES"));
  if (!tunables || setenv("GLIBC_TUNABLES", tunables->c_str(), 1) != 0) return;
  execv("/proc/self/exe", argv);
  // Not run again (no /proc): go on with malloc as it is.
#else
  (void)argv;
#endif
}

}  // namespace apps
