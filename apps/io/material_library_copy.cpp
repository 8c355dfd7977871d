#include "material_library_copy.h"

#include "Asset_folder.h"
#include "Io_error.h"
#include "material_texture.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <sstream>

namespace fs = std::filesystem;

namespace cgal_policies {
namespace io {
namespace {

// The bytes of the file at `path`; none when it cannot be read.
std::optional<std::string> file_bytes(const fs::path& path) {
  std::error_code failed;
  if (!fs::is_regular_file(path, failed)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  std::string bytes(std::istreambuf_iterator<char>(in), {});
  if (!in.good() && !in.eof()) return std::nullopt;
  return bytes;
}

}  // namespace

Material_library_copy material_library_copy(const Material_references& materials,
                                            const std::string& path) {
  const fs::path obj(path);
  const Asset_folder folder = Asset_folder::holding(fs::absolute(obj).parent_path());
  const std::string stem = obj.stem().string();
  Material_library_copy copy;
  std::map<fs::path, std::string> copied;  // each texture file copied, by its path: its new name
  std::size_t libraries_copied = 0;
  for (const std::string& library : materials.libraries) {
    const Asset_folder::Resolved inside = folder.check(library);
    const std::optional<std::string> text = file_bytes(library);
    if (!text) {
      if (inside.refusal.empty())  // named as it is: nothing outside the folder
        copy.names.push_back(inside.path.lexically_relative(folder.root()).string());
      else
        copy.left_out.push_back(library + ": cannot be read; written without it");
      continue;
    }
    // Each texture line as the copy writes it, and whether the library as it is would name a file
    // outside the OBJ's folder (a line refused by the asset folder, or a texture elsewhere): then
    // it is copied, even from the OBJ's folder.
    const Asset_folder asset(library, materials.asset_root);
    const fs::path library_folder = fs::path(library).parent_path();
    std::istringstream lines(*text);
    std::string line, written;
    std::vector<std::string> left_out;
    std::vector<Material_library_copy::File> textures;
    bool names_outside = false;
    while (std::getline(lines, line)) {
      const std::optional<Texture_line> texture = texture_line(line);
      if (!texture) {
        written += line + "\n";
        continue;
      }
      const auto leave_out = [&](const std::string& cause) {
        left_out.push_back(library + ": texture " + Asset_folder::quoted(texture->file) + " " +
                           cause + "; written without it");
      };
      const Asset_folder::Resolved file = asset.resolve(library_folder, texture->file);
      if (!file.refusal.empty()) {
        leave_out(file.refusal);
        names_outside = true;
        continue;
      }
      std::string name;
      if (const Asset_folder::Resolved there = folder.check(file.path); there.refusal.empty()) {
        name = there.path.lexically_relative(folder.root()).generic_string();
      } else if (const auto known = copied.find(file.path); known != copied.end()) {
        name = known->second;
        names_outside = true;
      } else if (const std::optional<std::string> bytes = file_bytes(file.path)) {
        name = stem + "_" + file.path.filename().string();
        for (int n = 2; std::any_of(copied.begin(), copied.end(),
                                    [&](const auto& c) { return c.second == name; });
             ++n)
          name = stem + "_" + std::to_string(n) + "_" + file.path.filename().string();
        copied.emplace(file.path, name);
        textures.push_back({(obj.parent_path() / name).string(), *bytes});
        copy.sources.push_back(file.path.string());
        names_outside = true;
      } else {
        leave_out("does not exist or cannot be read");
        continue;
      }
      written += texture->keyword + (texture->options.empty() ? "" : " " + texture->options) + " " +
                 name + "\n";
    }
    if (inside.refusal.empty() && !names_outside) {
      copy.names.push_back(inside.path.lexically_relative(folder.root()).string());
      continue;
    }
    const auto numbered = [&](std::size_t n) {
      return stem + (n == 0 ? "" : "_" + std::to_string(n)) + ".mtl";
    };
    std::string name = numbered(libraries_copied);
    for (std::size_t n = libraries_copied + 1;
         std::find(copy.names.begin(), copy.names.end(), name) != copy.names.end(); ++n)
      name = numbered(n);
    copy.names.push_back(name);
    copy.sources.push_back(library);
    copy.files.insert(copy.files.begin() + std::ptrdiff_t(libraries_copied++),
                      {(obj.parent_path() / name).string(), written});
    copy.files.insert(copy.files.end(), textures.begin(), textures.end());
    copy.left_out.insert(copy.left_out.end(), left_out.begin(), left_out.end());
  }
  return copy;
}

void check_no_source_of(const Material_library_copy& copy, const std::vector<std::string>& files) {
  for (const std::string& file : files)
    for (const std::string& source : copy.sources) {
      std::error_code missing;  // a file that does not exist overwrites nothing
      if (fs::equivalent(file, source, missing))
        throw Io_error(Io_error::Kind::unwritable_output,
                       file + ": refusing to overwrite a file of the input");
    }
}

}  // namespace io
}  // namespace cgal_policies
