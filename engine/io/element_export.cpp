#include "io/element_export.h"

#include "elements/element_frame.h"
#include "io/coordinate_precision.h"
#include "io/shape_table.h"

#include "io/atomic_file.h"
#include "core/input_error.h"
#include "core/interrupted.h"

#include <glm/geometric.hpp>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace paver {
namespace {

// The CSV's kind column: V, E and F as the paper names them (F its future work), B for beads.
const char* kind_column(ElementKind kind) {
  switch (kind) {
    case ElementKind::Vertex: return ",V";
    case ElementKind::Edge: return ",E";
    case ElementKind::Face: return ",F";
    case ElementKind::Bead: return ",B";
  }
  return ",?";
}

}  // namespace

namespace {

using Colour = std::array<std::uint8_t, 3>;

// Elements is a struct of arrays; a short array would be read past its end.
void check_sizes(const Elements& e) {
  const std::size_t n = e.size();
  if (e.id.size() != n || e.source.size() != n || e.spec.size() != n || e.uv.size() != n || e.position.size() != n ||
      e.normal.size() != n || e.diameter.size() != n || e.shape.size() != n)
    throw std::invalid_argument("Elements: its arrays have different lengths");
}

// Collects output in a fixed buffer and hands it to the stream in large writes, so that millions
// of small values cost neither a stream call each nor a string of the whole file.
class ChunkedWriter {
public:
  // `stop` is polled at every flush (each MiB): a large export ends within moments of a Ctrl-C.
  explicit ChunkedWriter(std::ostream& out, const std::atomic<bool>* stop = nullptr)
      : out_(out), stop_(stop), buffer_(kCapacity) {}

  // At least `n` writable bytes (n <= kMaxReserve); finish with advance().
  char* room(std::size_t n) {
    if (used_ + n > buffer_.size()) flush();
    return buffer_.data() + used_;
  }
  void advance(const char* end) { used_ = static_cast<std::size_t>(end - buffer_.data()); }

  void text(std::string_view s) {
    if (s.size() > kMaxReserve) {
      flush();
      out_.write(s.data(), static_cast<std::streamsize>(s.size()));
      return;
    }
    char* p = room(s.size());
    s.copy(p, s.size());
    advance(p + s.size());
  }
  void character(char c) {
    char* p = room(1);
    *p = c;
    advance(p + 1);
  }
  // %.<precision>g without locale or printf parsing.
  void number(double value, int precision) {
    char* p = room(kNumberBytes);
    advance(std::to_chars(p, p + kNumberBytes, value, std::chars_format::general, precision).ptr);
  }
  // Shortest text that reads back as the same float (or double): what the PLY stores, and fast (Ryu).
  template <class Real>
  void shortest(Real value) {
    char* p = room(kNumberBytes);
    advance(std::to_chars(p, p + kNumberBytes, value).ptr);
  }
  void integer(long long value) {
    char* p = room(kNumberBytes);
    advance(std::to_chars(p, p + kNumberBytes, value).ptr);
  }

  void flush() {
    if (stop_ && stop_->load()) throw Interrupted();
    out_.write(buffer_.data(), static_cast<std::streamsize>(used_));
    used_ = 0;
  }

  static constexpr std::size_t kNumberBytes = 32;  // "-1.2345678901234567e-308" fits
  static constexpr std::size_t kMaxReserve = 4096;

private:
  static constexpr std::size_t kCapacity = std::size_t{1} << 20;
  std::ostream& out_;
  const std::atomic<bool>* stop_;
  std::vector<char> buffer_;
  std::size_t used_ = 0;
};

// Little endian whatever the host is: PLY says which order, and we promise this one.
char* put_u32_le(char* p, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) p[i] = static_cast<char>((v >> (8 * i)) & 0xffu);
  return p + 4;
}
char* put_f32_le(char* p, float v) { return put_u32_le(p, std::bit_cast<std::uint32_t>(v)); }
char* put_f64_le(char* p, double v) {
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(v);
  for (int i = 0; i < 8; ++i) p[i] = static_cast<char>((bits >> (8 * i)) & 0xffu);
  return p + 8;
}
char* put_i32_le(char* p, std::int32_t v) { return put_u32_le(p, static_cast<std::uint32_t>(v)); }
char* put_u8(char* p, std::uint8_t v) {
  *p = static_cast<char>(v);
  return p + 1;
}

// The one per-element transform every mesh writer uses: calls emit(i, shape, placed) for each
// element in order, with `placed` its shape's vertices as they sit on the surface.
template <class Emit>
void for_each_placed_element(const Elements& elements, const ShapeTable& shapes, Emit&& emit) {
  std::vector<glm::dvec3> placed;
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const ShapeMesh& shape = shapes[elements.shape[i]];
    const ElementFrame frame = element_frame(elements.normal[i]);
    placed.resize(shape.positions.size());
    for (std::size_t k = 0; k < placed.size(); ++k)
      placed[k] = place_shape_vertex(frame, elements.position[i], elements.diameter[i], glm::dvec3(shape.positions[k]));
    emit(i, shape, placed);
  }
}

// Calls visit(i, corners) for every triangle of every element i, its corners numbered from
// `first` over the elements' vertices laid end to end, as for_each_placed_element emits them.
template <class Visit>
void for_each_element_triangle(const Elements& elements, const ShapeTable& shapes, long long first, Visit&& visit) {
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const ShapeMesh& shape = shapes[elements.shape[i]];
    for (const glm::ivec3& t : shape.triangles) visit(i, glm::i64vec3(first + t.x, first + t.y, first + t.z));
    first += static_cast<long long>(shape.positions.size());
  }
}

struct MeshCounts {
  std::size_t vertices = 0;
  std::size_t faces = 0;
};

MeshCounts count(const Elements& elements, const ShapeTable& shapes) {
  MeshCounts c;
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const ShapeMesh& shape = shapes[elements.shape[i]];
    c.vertices += shape.positions.size();
    c.faces += shape.triangles.size();
  }
  return c;
}

const Elements& checked(const Elements& elements) {
  check_sizes(elements);
  return elements;
}

// What an element mesh writer needs: the elements' shapes (those of the design's custom shape
// named after `path`, the file written) and how many vertices and faces they make.
struct ElementMesh {
  ShapeTable shapes;
  MeshCounts counts;

  ElementMesh(const Elements& elements, const ShapeMesh* custom, const std::filesystem::path& path)
      : shapes(checked(elements), custom, path), counts(count(elements, shapes)) {}
};

// One binary STL triangle: its unit normal and three corners as float32, and a zero attribute word.
void put_stl_triangle(ChunkedWriter& w, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& d) {
  const glm::dvec3 cross = glm::cross(b - a, d - a);
  const double length = glm::length(cross);
  // A sliver gets a zero normal, which STL readers take as "compute it from the vertices".
  const glm::dvec3 n = length > 0 && std::isfinite(length) ? cross / length : glm::dvec3(0);
  char* p = w.room(50);
  for (const glm::dvec3& v : {n, a, b, d}) {
    p = put_f32_le(p, static_cast<float>(v.x));
    p = put_f32_le(p, static_cast<float>(v.y));
    p = put_f32_le(p, static_cast<float>(v.z));
  }
  p = put_u8(p, 0);  // attribute byte count: unused
  p = put_u8(p, 0);
  w.advance(p);
}

void put_stl_header(ChunkedWriter& w, std::string header, std::size_t faces) {
  header.resize(80, ' ');  // the 80-byte header must not start with "solid" (ASCII STL)
  w.text(header);
  char* c = w.room(4);
  w.advance(put_u32_le(c, static_cast<std::uint32_t>(faces)));
}

}  // namespace

void write_placements_csv(const std::filesystem::path& path, const Elements& elements,
                          const std::atomic<bool>* stop) {
  check_sizes(elements);
  write_file_atomically(path, [&](std::ostream& out) {
    constexpr int kDigits = 17;  // enough for every double to read back exactly
    ChunkedWriter w(out, stop);
    w.text("id,kind,x,y,z,nx,ny,nz,diameter,u,v\n");
    for (std::size_t i = 0; i < elements.size(); ++i) {
      // Unnumbered elements (a caller that placed them itself) are listed by their index.
      w.integer(static_cast<long long>(elements.id[i] == kNoElementId ? int(i) : elements.id[i]));
      w.text(kind_column(elements.kind[i]));
      for (const double value :
           {elements.position[i].x, elements.position[i].y, elements.position[i].z,
            elements.normal[i].x, elements.normal[i].y, elements.normal[i].z, elements.diameter[i],
            elements.uv[i].x, elements.uv[i].y}) {
        w.character(',');
        w.number(value, kDigits);
      }
      w.character('\n');
    }
    w.flush();
  });
}

ElementMeshSize element_mesh_size(const Elements& elements, const ElementMeshOptions& options) {
  const ElementMesh mesh(elements, options.custom, "elements");
  return {elements.size(), mesh.counts.vertices, mesh.counts.faces};
}

ElementMeshSize shape_mesh_size(ShapeKind kind, std::size_t count, const ShapeMesh* custom) {
  if (kind == ShapeKind::Custom && !custom)
    throw std::invalid_argument("shape_mesh_size: the design uses the custom shape but none was given");
  const ShapeMesh builtin = kind == ShapeKind::Custom ? ShapeMesh{} : make_builtin_shape(kind);
  const ShapeMesh& shape = kind == ShapeKind::Custom ? *custom : builtin;
  return {count, count * shape.positions.size(), count * shape.triangles.size()};
}

ElementMeshSize expected_element_mesh_size(const Pattern& pattern, const ElementsDesign& design,
                                           const ElementMeshOptions& options) {
  ElementMeshSize size;
  const auto add = [&](ShapeKind kind, std::size_t count) {
    if (count == 0) return;
    const ElementMeshSize more = shape_mesh_size(kind, count, options.custom);
    size.elements += more.elements;
    size.vertices += more.vertices;
    size.faces += more.faces;
  };
  if (design.vertex.enabled) add(design.vertex.shape, std::size_t(pattern.point_count()));
  for (const EdgeElementDesign& spec : design.edge) {
    std::size_t count = 0;
    for (int e = 0; e < pattern.edge_count(); ++e)
      count += !pattern.edge_virtual[e] && spec.sits_on(pattern.edge_cell_edge[e]);
    add(spec.shape, count);
  }
  return size;
}

void write_elements_ply(const std::filesystem::path& path, const Elements& elements,
                        const ElementMeshOptions& options) {
  if (options.colours && options.colours->size() != elements.size())
    throw std::invalid_argument("write_elements_ply: colours must have one entry per element");
  const ElementMesh mesh(elements, options.custom, path);
  // PLY vertex indices are 32-bit signed.
  if (mesh.counts.vertices > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    throw InputError("cannot write " + path.string() + ": its " + std::to_string(mesh.counts.vertices) +
                     " vertices are more than PLY indices can address; use fewer elements or a "
                     "lighter shape");

  // Double only where float32 would not hold the elements (io/coordinate_precision.h), so a file
  // near the origin stays the float32 PLY every tool reads.
  const bool wide = !float32_holds(elements);
  const std::string real = wide ? "double" : "float";
  write_file_atomically(path, [&](std::ostream& out) {
    ChunkedWriter w(out, options.stop);
    w.text("ply\nformat binary_little_endian 1.0\ncomment Paver elements: " +
           std::to_string(elements.size()) + "\nelement vertex " + std::to_string(mesh.counts.vertices) +
           "\nproperty " + real + " x\nproperty " + real + " y\nproperty " + real + " z\n"
           "property uchar red\nproperty uchar green\nproperty uchar blue\n"
           "element face " + std::to_string(mesh.counts.faces) +
           "\nproperty list uchar int vertex_indices\nend_header\n");

    for_each_placed_element(elements, mesh.shapes, [&](std::size_t i, const ShapeMesh&, const std::vector<glm::dvec3>& placed) {
      const Colour colour = options.colours ? (*options.colours)[i] : kind_colour(elements.kind[i]);
      for (const glm::dvec3& p : placed) {
        char* c = w.room(27);
        for (int axis = 0; axis < 3; ++axis)
          c = wide ? put_f64_le(c, p[axis]) : put_f32_le(c, static_cast<float>(p[axis]));
        for (const std::uint8_t channel : colour) c = put_u8(c, channel);
        w.advance(c);
      }
    });

    for_each_element_triangle(elements, mesh.shapes, 0, [&](std::size_t, const glm::i64vec3& corners) {
      char* c = w.room(13);
      c = put_u8(c, 3);
      for (int k = 0; k < 3; ++k) c = put_i32_le(c, static_cast<std::int32_t>(corners[k]));
      w.advance(c);
    });
    w.flush();
  });
}

void write_elements_obj(const std::filesystem::path& path, const Elements& elements,
                        const ElementMeshOptions& options) {
  const ElementMesh mesh(elements, options.custom, path);

  write_file_atomically(path, [&](std::ostream& out) {
    ChunkedWriter w(out, options.stop);
    w.text("# Paver elements: " + std::to_string(elements.size()) + "\n# vertices: " +
           std::to_string(mesh.counts.vertices) + ", faces: " + std::to_string(mesh.counts.faces) + "\n");

    const bool wide = !float32_holds(elements);  // as the PLY
    for_each_placed_element(elements, mesh.shapes, [&](std::size_t, const ShapeMesh&, const std::vector<glm::dvec3>& placed) {
      for (const glm::dvec3& p : placed) {
        w.text("v");
        for (int axis = 0; axis < 3; ++axis) {
          w.character(' ');
          if (wide) w.shortest(p[axis]);
          else w.shortest(static_cast<float>(p[axis]));
        }
        w.character('\n');
      }
    });

    // Stones and beads as two groups, so a CAD tool can select the metal's beads apart from the
    // stones (they could only be told apart by connectivity). OBJ counts vertices from 1.
    const char* group = nullptr;
    for_each_element_triangle(elements, mesh.shapes, 1, [&](std::size_t i, const glm::i64vec3& corners) {
      const char* wanted = elements.kind[i] == ElementKind::Bead ? "g beads\n" : "g stones\n";
      if (wanted != group) w.text(group = wanted);
      w.character('f');
      for (int k = 0; k < 3; ++k) {
        w.character(' ');
        w.integer(corners[k]);
      }
      w.character('\n');
    });
    w.flush();
  });
}

void write_elements_stl(const std::filesystem::path& path, const Elements& elements,
                        const ElementMeshOptions& options) {
  const ElementMesh mesh(elements, options.custom, path);
  if (mesh.counts.faces > std::numeric_limits<std::uint32_t>::max())
    throw InputError("cannot write " + path.string() + ": its " + std::to_string(mesh.counts.faces) +
                     " triangles are more than binary STL can count; use fewer elements or a lighter shape");

  write_file_atomically(path, [&](std::ostream& out) {
    ChunkedWriter w(out, options.stop);
    put_stl_header(w, "Paver elements: " + std::to_string(elements.size()), mesh.counts.faces);

    for_each_placed_element(elements, mesh.shapes, [&](std::size_t, const ShapeMesh& shape, const std::vector<glm::dvec3>& placed) {
      for (const glm::ivec3& t : shape.triangles) put_stl_triangle(w, placed[t.x], placed[t.y], placed[t.z]);
    });
    w.flush();
  });
}

void write_mesh_stl(const std::filesystem::path& path, const SurfaceMesh& mesh, const std::string& title,
                    const std::atomic<bool>* stop) {
  if (mesh.triangles.size() > std::numeric_limits<std::uint32_t>::max())
    throw InputError("cannot write " + path.string() + ": its " + std::to_string(mesh.triangles.size()) +
                     " triangles are more than binary STL can count");
  write_file_atomically(path, [&](std::ostream& out) {
    ChunkedWriter w(out, stop);
    put_stl_header(w, "Paver " + title, mesh.triangles.size());
    for (const glm::ivec3& t : mesh.triangles)
      put_stl_triangle(w, mesh.positions[std::size_t(t.x)], mesh.positions[std::size_t(t.y)],
                       mesh.positions[std::size_t(t.z)]);
    w.flush();
  });
}

}  // namespace paver
