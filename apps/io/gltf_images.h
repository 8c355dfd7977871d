// The images of a glTF file's looks (gltf_io.h) and the files they name: the texture references
// of a material, the images left out (an image an asset may not name, or a file a written file
// cannot embed), and the image files a written file names or embeds (docs/reliability.md, "What
// an asset can make the tools read").
#ifndef CGAL_POLICIES_IO_GLTF_IMAGES_H
#define CGAL_POLICIES_IO_GLTF_IMAGES_H

#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace cgal_policies {
namespace io {

// Calls visit(info) for each texture reference of `material` (a tinygltf::Material, const or not),
// the base colour texture first.
template <class Material, class Visit>
void for_each_texture(Material& material, const Visit& visit) {
  visit(material.pbrMetallicRoughness.baseColorTexture);
  visit(material.pbrMetallicRoughness.metallicRoughnessTexture);
  visit(material.normalTexture);
  visit(material.occlusionTexture);
  visit(material.emissiveTexture);
}

// Removes the images that `removed` marks from `looks`: a texture that showed one shows none, and
// no material refers to it any more; the other images keep their order.
void remove_images(tinygltf::Model& looks, const std::vector<bool>& removed);

// The bytes of the image file at `path` and their mimeType (image_mime_type), for a written file
// to embed; why not, when it cannot be read or is neither a PNG nor a JPEG image.
struct Image_file {
  std::vector<unsigned char> bytes;
  std::string mime_type;
  std::string failure;  // empty when read
};
Image_file read_image_file(const std::string& path);

}  // namespace io
}  // namespace cgal_policies

#endif  // CGAL_POLICIES_IO_GLTF_IMAGES_H
