#include "material_texture.h"

#include "Io_error.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

namespace cgal_policies {
namespace io {

namespace {

// How many arguments each option of a texture line takes, at most (the .mtl format's own; an
// argument is a word that is not an option and, but for -imfchan's and -type's, a number or
// on/off).
int option_arguments(const std::string& option) {
  if (option == "-o" || option == "-s" || option == "-t") return 3;
  if (option == "-mm") return 2;
  return 1;
}

bool is_argument(const std::string& option, const std::string& word) {
  if (word.empty() || word[0] == '-') {
    char* end = nullptr;
    std::strtod(word.c_str(), &end);
    return !word.empty() && end == word.c_str() + word.size();  // a negative number
  }
  if (option == "-imfchan" || option == "-type") return true;
  if (word == "on" || word == "off") return true;
  char* end = nullptr;
  std::strtod(word.c_str(), &end);
  return end == word.c_str() + word.size();
}

bool names_texture(const std::string& keyword) {
  static const char* const kMaps[] = {"bump", "disp", "decal", "refl", "norm"};
  return keyword.rfind("map_", 0) == 0 ||
         std::find(std::begin(kMaps), std::end(kMaps), keyword) != std::end(kMaps);
}

}  // namespace

std::optional<Texture_line> texture_line(const std::string& line) {
  // The words with where each starts, up to the file.
  std::size_t at = 0;
  const auto next_word = [&]() {
    const std::size_t start = line.find_first_not_of(" \t\r", at);
    if (start == std::string::npos) return std::make_pair(line.size(), std::string());
    at = line.find_first_of(" \t\r", start);
    if (at == std::string::npos) at = line.size();
    return std::make_pair(start, line.substr(start, at - start));
  };
  Texture_line texture;
  texture.keyword = next_word().second;
  if (!names_texture(texture.keyword)) return std::nullopt;
  std::string option;
  int arguments_left = 0;
  for (;;) {
    const auto [start, word] = next_word();
    if (word.empty()) return std::nullopt;
    if (arguments_left > 0 && is_argument(option, word)) {
      --arguments_left;
    } else if (word[0] == '-') {
      option = word;
      arguments_left = option_arguments(word);
    } else {
      texture.file = line.substr(start);
      texture.file.erase(texture.file.find_last_not_of(" \t\r") + 1);
      return texture;
    }
    texture.options += (texture.options.empty() ? "" : " ") + word;
  }
}

std::vector<std::string> material_library_paths(const std::string& path,
                                                const std::vector<std::string>& libraries,
                                                const Asset_folder& folder,
                                                std::vector<std::string>& left_out) {
  const std::filesystem::path obj_folder = std::filesystem::absolute(path).parent_path();
  std::vector<std::string> paths;
  for (const std::string& library : libraries) {
    const Asset_folder::Resolved resolved = folder.resolve(obj_folder, library);
    if (resolved.refusal.empty())
      paths.push_back(resolved.path.string());
    else
      left_out.push_back(path + ": material library " + Asset_folder::quoted(library) + " " +
                         resolved.refusal + "; read without it");
  }
  return paths;
}

std::vector<std::optional<Diffuse_map>> diffuse_maps(const Material_references& materials) {
  // The first map of each material, by name, over all libraries.
  std::map<std::string, Diffuse_map> maps;
  for (const std::string& library : materials.libraries) {
    const Asset_folder folder(library, materials.asset_root);
    std::ifstream in(library);
    std::string line, material;
    while (std::getline(in, line)) {
      std::istringstream words(line);
      std::string keyword;
      words >> keyword;
      if (keyword == "newmtl") {
        std::getline(words >> std::ws, material);
        material.erase(material.find_last_not_of(" \t\r") + 1);
      } else if (keyword == "map_Kd" && !material.empty()) {
        const std::optional<Texture_line> map = texture_line(line);
        if (!map) continue;
        const Asset_folder::Resolved resolved =
            folder.resolve(std::filesystem::path(library).parent_path(), map->file);
        maps.emplace(material,
                     Diffuse_map{library, map->file, resolved.path.string(), resolved.refusal});
      }
    }
  }
  std::vector<std::optional<Diffuse_map>> of_names;
  for (const std::string& name : materials.names) {
    const auto found = maps.find(name);
    of_names.push_back(found == maps.end() ? std::nullopt
                                           : std::optional<Diffuse_map>(found->second));
  }
  return of_names;
}

std::optional<std::string> diffuse_texture_file(const Material_references& materials) {
  for (const std::optional<Diffuse_map>& map : diffuse_maps(materials)) {
    if (!map) continue;
    if (!map->refusal.empty())
      throw Io_error(
          Io_error::Kind::unreadable_input,
          map->library + ": texture " + Asset_folder::quoted(map->file) + " " + map->refusal);
    if (!std::filesystem::is_regular_file(map->path))
      throw Io_error(
          Io_error::Kind::unreadable_input,
          map->library + ": texture " + Asset_folder::quoted(map->file) + " does not exist");
    return map->path;
  }
  return std::nullopt;
}

std::string image_mime_type(const std::vector<unsigned char>& bytes) {
  static const std::vector<unsigned char> kPng = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  static const std::vector<unsigned char> kJpeg = {0xff, 0xd8, 0xff};
  const auto starts_with = [&bytes](const std::vector<unsigned char>& signature) {
    return bytes.size() >= signature.size() &&
           std::equal(signature.begin(), signature.end(), bytes.begin());
  };
  return starts_with(kPng) ? "image/png" : starts_with(kJpeg) ? "image/jpeg" : "";
}

}  // namespace io
}  // namespace cgal_policies
