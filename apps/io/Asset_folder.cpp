#include "Asset_folder.h"

#include "Io_error.h"

#include <algorithm>
#include <cctype>
#include <system_error>

namespace fs = std::filesystem;

namespace cgal_policies {
namespace io {
namespace {

// Longer references are no file name any system takes (PATH_MAX).
constexpr std::size_t kLongestReference = 4096;

// `path` made absolute and normalised, without a trailing separator.
fs::path normal_absolute(const fs::path& path) {
  fs::path normal = fs::absolute(path).lexically_normal();
  if (!normal.has_filename() && normal.has_relative_path()) normal = normal.parent_path();
  return normal;
}

// `path` with its symbolic links resolved as far as it exists; empty when that fails (a name too
// long for the system, a loop of links).
fs::path resolved_links(const fs::path& path) {
  std::error_code failed;
  fs::path resolved = fs::weakly_canonical(path, failed);
  if (failed) return {};
  return normal_absolute(resolved);
}

std::string with_slashes(std::string text) {
  std::replace(text.begin(), text.end(), '\\', '/');
  return text;
}

// RFC 3986's scheme: a letter, then letters, digits, '+', '-' or '.', then ':', before any '/'.
// A Windows drive ("C:") is one too, and no relative path either.
bool has_scheme(const std::string& reference) {
  const std::size_t colon = reference.find(':');
  if (colon == std::string::npos || colon == 0 || reference.find('/') < colon) return false;
  if (!std::isalpha(static_cast<unsigned char>(reference[0]))) return false;
  return std::all_of(reference.begin(), reference.begin() + std::ptrdiff_t(colon), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '+' || c == '-' || c == '.';
  });
}

}  // namespace

Asset_folder::Asset_folder(const std::string& asset_path, const std::string& root)
    : m_spelled_root(
          normal_absolute(root.empty() ? fs::absolute(asset_path).parent_path() : fs::path(root))),
      m_root(resolved_links(m_spelled_root)) {
  if (m_root.empty()) m_root = m_spelled_root;
  if (!root.empty() && !lexically_inside(m_root, resolved_links(fs::absolute(asset_path))))
    throw Io_error(Io_error::Kind::unreadable_input,
                   asset_path + ": not inside the asset root " + root);
}

Asset_folder Asset_folder::holding(const fs::path& folder) {
  Asset_folder holding;
  holding.m_spelled_root = normal_absolute(folder);
  holding.m_root = resolved_links(holding.m_spelled_root);
  if (holding.m_root.empty()) holding.m_root = holding.m_spelled_root;
  return holding;
}

Asset_folder::Resolved Asset_folder::resolve(const fs::path& referring_folder,
                                             const std::string& reference) const {
  if (reference.empty()) return {{}, "is empty"};
  if (reference.size() > kLongestReference) return {{}, "is too long"};
  if (std::any_of(reference.begin(), reference.end(),
                  [](char c) { return static_cast<unsigned char>(c) < 0x20; }))
    return {{}, "holds a control character"};
  const std::string path = with_slashes(reference);
  if (has_scheme(path))
    return {{}, "is a URI with a scheme; only paths relative to the asset are read"};
  if (path.front() == '/')
    return {{}, "is an absolute path; only paths relative to the asset are read"};
  return inside_root(fs::absolute(referring_folder) / path);
}

Asset_folder::Resolved Asset_folder::check(const fs::path& path) const {
  if (path.empty()) return {{}, "is empty"};
  return inside_root(fs::absolute(path));
}

std::string Asset_folder::quoted(const std::string& reference) {
  static const char kHex[] = "0123456789abcdef";
  std::string quoted = "'";
  for (const char c : reference.substr(0, 200)) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7f)
      quoted += {'\\', 'x', kHex[byte >> 4], kHex[byte & 15]};
    else
      quoted += c;
  }
  return quoted + "'";
}

bool Asset_folder::lexically_inside(const fs::path& folder, const fs::path& path) {
  const fs::path outer = normal_absolute(folder), inner = normal_absolute(path);
  return std::mismatch(outer.begin(), outer.end(), inner.begin(), inner.end()).first == outer.end();
}

Asset_folder::Resolved Asset_folder::inside_root(const fs::path& path) const {
  // ".." taken as written: a reference that climbs out is refused without a look at the disk.
  // The root may be spelled either way, as the asset's path names it or resolved.
  const fs::path normal = normal_absolute(path);
  if (!lexically_inside(m_spelled_root, normal) && !lexically_inside(m_root, normal))
    return {{}, "leads outside the asset's folder"};
  // Then every link resolved. With no ".." left, what follows a folder that does not exist cannot
  // exist either, so no link hides behind one ("missing/../link"). The file read is the resolved
  // one: what was checked is what is opened. One reason for a link out and for a path that
  // cannot be resolved (a loop of links, a name too long): it says nothing of the disk outside.
  const fs::path resolved = resolved_links(normal);
  if (resolved.empty() || !lexically_inside(m_root, resolved))
    return {{}, "leads outside the asset's folder through a symbolic link, or cannot be resolved"};
  return {resolved, ""};
}

}  // namespace io
}  // namespace cgal_policies
