#include "material_texture.h"

#include "Io_error.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace cgal_policies {
namespace io {

std::vector<std::optional<Diffuse_map>> diffuse_maps(const Material_references& materials) {
  // The first map of each material, by name, over all libraries.
  std::map<std::string, Diffuse_map> maps;
  for (const std::string& library : materials.libraries) {
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
        // Options come first (-s 1 1 1, -clamp on, ...); the file name is the last word.
        std::string word, file;
        while (words >> word) file = word;
        if (!file.empty())
          maps.emplace(material, Diffuse_map{library, file,
                                             (std::filesystem::path(library).parent_path() / file)
                                                 .lexically_normal()
                                                 .string()});
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
    if (!std::filesystem::is_regular_file(map->path))
      throw Io_error(Io_error::Kind::unreadable_input,
                     map->library + ": texture '" + map->file + "' does not exist");
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
