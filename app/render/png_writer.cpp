#include "renderer.h"

#include "io/atomic_file.h"
#include "core/input_error.h"

#include <stb_image_write.h>  // the implementation is in Debian's libstb

#include <string>
#include <vector>

namespace paver::render {

void write_png(const std::filesystem::path& path, const Image& image) {
  std::vector<unsigned char> bytes;
  auto append = [](void* context, void* data, int size) {
    auto* out = static_cast<std::vector<unsigned char>*>(context);
    const auto* p = static_cast<const unsigned char*>(data);
    out->insert(out->end(), p, p + size);
  };
  if (image.width <= 0 || image.height <= 0 ||
      !stbi_write_png_to_func(append, &bytes, image.width, image.height, 4, image.rgba.data(), image.width * 4))
    throw InputError("cannot encode " + path.string() + " as PNG");
  write_file_atomically(path, [&](std::ostream& out) {
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  });
}

}  // namespace paver::render
