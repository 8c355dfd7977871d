#include "material_texture.h"

#include "Io_error.h"

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace cgal_policies {
namespace io {

std::optional<std::string> diffuse_texture_file(const Material_references& materials) {
  // The first map of each material, by name, over all libraries.
  std::map<std::string, std::pair<std::string, std::string>> maps;  // name -> (library, file)
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
        if (!file.empty()) maps.emplace(material, std::make_pair(library, file));
      }
    }
  }
  for (const std::string& name : materials.names) {
    const auto found = maps.find(name);
    if (found == maps.end()) continue;
    const auto& [library, file] = found->second;
    const std::filesystem::path path = std::filesystem::path(library).parent_path() / file;
    if (!std::filesystem::is_regular_file(path))
      throw Io_error(Io_error::Kind::unreadable_input,
                     library + ": texture '" + file + "' does not exist");
    return path.string();
  }
  return std::nullopt;
}

}  // namespace io
}  // namespace cgal_policies
