// The folder the files an asset names may come from. A glTF file names buffers and images, an OBJ
// file material libraries, which name texture images; the asset is often somebody else's (an
// upload, a download), so what it names is read only from the folder of the file the user opened,
// or a folder below, or from a wider root the user names for trusted local use
// (docs/reliability.md, "What an asset can make the tools read"). A reference is refused, before
// any file is opened, when it is empty, too long, holds a control character, is absolute or a URI
// with a scheme (file:, http:, ...), leaves the folder through "..", or reaches outside it through
// a symbolic link. Backslashes separate folders, as in assets made on Windows. A data URI that
// tinygltf decodes is not a file and never comes here; one of another type is refused as a
// scheme.
#ifndef CGAL_POLICIES_IO_ASSET_FOLDER_H
#define CGAL_POLICIES_IO_ASSET_FOLDER_H

#include <filesystem>
#include <string>

namespace cgal_policies {
namespace io {

class Asset_folder {
 public:
  // The folder of the asset file at `asset_path`, or `root` when it is not empty: a folder that
  // must hold that file, else Io_error (unreadable input, "<asset_path>: not inside the asset root
  // <root>").
  explicit Asset_folder(const std::string& asset_path, const std::string& root = {});

  // The folder itself: a written file's, which names only files inside it.
  static Asset_folder holding(const std::filesystem::path& folder);

  // A file named from the folder `referring_folder` (inside the root), or why it is refused.
  struct Resolved {
    std::filesystem::path path;  // empty when refused
    std::string refusal;         // "leads outside the asset's folder", ...; empty when not
    // (".." is taken as written, before any link: "link/../x" is the root's x, the file read.)
  };
  Resolved resolve(const std::filesystem::path& referring_folder,
                   const std::string& reference) const;

  // A path of this process's own (a file resolved from an asset before), checked as resolve
  // checks a reference's: whether it lies in the root, its links followed.
  Resolved check(const std::filesystem::path& path) const;

  // A reference as a message quotes it: its first 200 bytes, each control character as \xNN, so
  // that the message stays one line.
  static std::string quoted(const std::string& reference);

  // Whether `path` lies in `folder` or a folder below it, both taken as they are spelled after
  // lexical normalisation (for a written file's folder, which the user chose).
  static bool lexically_inside(const std::filesystem::path& folder,
                               const std::filesystem::path& path);

  // The root, absolute and with its symbolic links resolved.
  const std::filesystem::path& root() const { return m_root; }

 private:
  Asset_folder() = default;
  Resolved inside_root(const std::filesystem::path& path) const;

  std::filesystem::path m_spelled_root;  // absolute, as the asset's path or the option spell it
  std::filesystem::path m_root;          // the same, its symbolic links resolved
};

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_ASSET_FOLDER_H
