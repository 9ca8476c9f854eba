// glTF 2.0, as .gltf (JSON with external or embedded buffers) or .glb, parsed by tinygltf.
// The node hierarchy places every mesh; each triangle, strip or fan primitive becomes
// triangles in the soup. Points and lines bound no surface and are skipped with a warning.
#include <tiny_gltf.h>

#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "json_text.h"
#include "readers.h"
#include "shadowkit/scene/limits.h"
#include "skipped_items.h"
#include "text_cursor.h"

namespace shadowkit::mesh_io {
namespace {

/// \brief An affine map of glTF's column-major 4x4 matrices, in double.
struct Affine {
  std::array<double, 16> m{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

  Vec3 apply(Vec3 p) const {
    return {m[0] * p.x + m[4] * p.y + m[8] * p.z + m[12],
            m[1] * p.x + m[5] * p.y + m[9] * p.z + m[13],
            m[2] * p.x + m[6] * p.y + m[10] * p.z + m[14]};
  }
  Affine operator*(const Affine& b) const {
    Affine c;
    for (int col = 0; col < 4; ++col) {
      for (int row = 0; row < 4; ++row) {
        double sum = 0;
        for (int k = 0; k < 4; ++k) sum += m[k * 4 + row] * b.m[col * 4 + k];
        c.m[col * 4 + row] = sum;
      }
    }
    return c;
  }
};

/// \brief Errors and warnings of one file, located by JSON path ("file: key 'nodes[3]'").
class GltfSource {
 public:
  GltfSource(const tinygltf::Model& model, const std::string& path) : model_(model), path_(path) {}

  const tinygltf::Model& model() const { return model_; }
  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw InputError(path_ + ": key '" + key + "'", what);
  }
  /// \p index as an index into an array of \p size items, or an error naming \p key.
  std::size_t index(int index, std::size_t size, const std::string& key) const {
    if (index < 0 || static_cast<std::size_t>(index) >= size) {
      fail(key, "index " + std::to_string(index) + " is out of range (" + std::to_string(size) +
                    " defined)");
    }
    return static_cast<std::size_t>(index);
  }

 private:
  const tinygltf::Model& model_;
  const std::string& path_;
};

// The local transform of a node: its matrix, or T * R * S (glTF 2.0 §3.5.3).
Affine local_transform(const tinygltf::Node& node, const GltfSource& src, std::size_t n) {
  const std::string key = "nodes[" + std::to_string(n) + "]";
  auto finite = [&](const std::vector<double>& values, std::size_t size, const char* name) {
    if (values.empty()) return false;
    if (values.size() != size) {
      src.fail(key + "." + name, "expected " + std::to_string(size) + " numbers");
    }
    for (double v : values) {
      if (!std::isfinite(v)) src.fail(key + "." + name, "holds a non-finite number");
    }
    return true;
  };
  Affine a;
  if (finite(node.matrix, 16, "matrix")) {
    std::copy(node.matrix.begin(), node.matrix.end(), a.m.begin());
    return a;
  }
  Affine t, r, s;
  if (finite(node.translation, 3, "translation")) {
    t.m[12] = node.translation[0], t.m[13] = node.translation[1], t.m[14] = node.translation[2];
  }
  if (finite(node.rotation, 4, "rotation")) {
    double x = node.rotation[0], y = node.rotation[1], z = node.rotation[2], w = node.rotation[3];
    const double norm = std::sqrt(x * x + y * y + z * z + w * w);
    if (!(norm > 0)) src.fail(key + ".rotation", "is not a rotation (a zero quaternion)");
    x /= norm, y /= norm, z /= norm, w /= norm;
    r.m = {1 - 2 * (y * y + z * z),
           2 * (x * y + z * w),
           2 * (x * z - y * w),
           0,
           2 * (x * y - z * w),
           1 - 2 * (x * x + z * z),
           2 * (y * z + x * w),
           0,
           2 * (x * z + y * w),
           2 * (y * z - x * w),
           1 - 2 * (x * x + y * y),
           0,
           0,
           0,
           0,
           1};
  }
  if (finite(node.scale, 3, "scale")) {
    s.m[0] = node.scale[0], s.m[5] = node.scale[1], s.m[10] = node.scale[2];
  }
  return t * r * s;
}

std::size_t component_count(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return 1;
    case TINYGLTF_TYPE_VEC2:
      return 2;
    case TINYGLTF_TYPE_VEC3:
      return 3;
    case TINYGLTF_TYPE_VEC4:
      return 4;
    default:
      return 0;
  }
}

std::size_t component_bytes(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    case TINYGLTF_COMPONENT_TYPE_INT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return 4;
    default:
      return 0;
  }
}

template <typename T>
T load(const unsigned char* bytes) {
  T value;
  std::memcpy(&value, bytes, sizeof value);  // glTF is little-endian, as is every target here
  return value;
}

// One component as a number; normalized integers map to [-1, 1] or [0, 1] (§3.11).
double component(const unsigned char* bytes, int type, bool normalized) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      return normalized ? std::max(load<std::int8_t>(bytes) / 127.0, -1.0)
                        : load<std::int8_t>(bytes);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return normalized ? load<std::uint8_t>(bytes) / 255.0 : load<std::uint8_t>(bytes);
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      return normalized ? std::max(load<std::int16_t>(bytes) / 32767.0, -1.0)
                        : load<std::int16_t>(bytes);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return normalized ? load<std::uint16_t>(bytes) / 65535.0 : load<std::uint16_t>(bytes);
    case TINYGLTF_COMPONENT_TYPE_INT:
      return load<std::int32_t>(bytes);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return load<std::uint32_t>(bytes);
    default:
      return load<float>(bytes);
  }
}

/// \brief The bytes of one buffer view's stretch, checked against the buffer they lie in.
struct ByteRange {
  const unsigned char* data = nullptr;
  std::size_t size = 0;
  std::size_t stride = 0;  // 0: tightly packed
};

ByteRange view_bytes(const GltfSource& src, int view_index, const std::string& key) {
  const tinygltf::Model& model = src.model();
  const std::size_t v = src.index(view_index, model.bufferViews.size(), key);
  const tinygltf::BufferView& view = model.bufferViews[v];
  const std::string view_key = "bufferViews[" + std::to_string(v) + "]";
  const std::size_t b = src.index(view.buffer, model.buffers.size(), view_key + ".buffer");
  const std::vector<unsigned char>& buffer = model.buffers[b].data;
  if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset) {
    src.fail(view_key, "bytes " + std::to_string(view.byteOffset) + " to " +
                           std::to_string(view.byteOffset + view.byteLength) +
                           " lie beyond its buffer's " + std::to_string(buffer.size()) + " bytes");
  }
  return {buffer.data() + view.byteOffset, view.byteLength, view.byteStride};
}

/// \brief An accessor's elements as doubles, bounds-checked once (sparse accessors too).
class AccessorValues {
 public:
  AccessorValues(const GltfSource& src, std::size_t a)
      : key_("accessors[" + std::to_string(a) + "]") {
    const tinygltf::Accessor& acc = src.model().accessors[a];
    components_ = component_count(acc.type);
    const std::size_t bytes = component_bytes(acc.componentType);
    if (components_ == 0 || bytes == 0) src.fail(key_, "has an unknown type or componentType");
    // Elements in a buffer view cost what the file holds; elements without one are zeros
    // (§3.6.2.1) that cost only what the count claims, so the count is bounded.
    if (acc.bufferView < 0 && acc.count > limits::kPolygons) {
      src.fail(key_ + ".count", std::to_string(acc.count) +
                                    " elements without a bufferView are more than " +
                                    std::to_string(limits::kPolygons) + " allowed");
    }
    ByteRange range;
    std::size_t stride = 0;
    if (acc.bufferView >= 0) {
      range = view_bytes(src, acc.bufferView, key_ + ".bufferView");
      const std::size_t element = bytes * components_;
      stride = range.stride != 0 ? range.stride : element;
      if (stride < element)
        src.fail(key_, "its buffer view's byteStride is below its element size");
      const std::size_t room = range.size - std::min(acc.byteOffset, range.size);
      if (acc.count > 0 && (acc.byteOffset > range.size || element > room ||
                            acc.count - 1 > (room - element) / stride)) {
        src.fail(key_, std::to_string(acc.count) + " elements from byte " +
                           std::to_string(acc.byteOffset) + " do not fit its buffer view's " +
                           std::to_string(range.size) + " bytes");
      }
    }
    values_.assign(acc.count * components_, 0.0);
    if (range.data != nullptr) {
      for (std::size_t i = 0; i < acc.count; ++i) {
        const unsigned char* at = range.data + acc.byteOffset + i * stride;
        for (std::size_t c = 0; c < components_; ++c) {
          values_[i * components_ + c] =
              component(at + c * bytes, acc.componentType, acc.normalized);
        }
      }
    }
    if (acc.sparse.isSparse) apply_sparse(src, acc, bytes);
  }

  std::size_t count() const { return values_.size() / std::max<std::size_t>(components_, 1); }
  std::size_t components() const { return components_; }
  double at(std::size_t element, std::size_t c = 0) const {
    return values_[element * components_ + c];
  }
  const std::string& key() const { return key_; }

 private:
  // Sparse substitution (§3.6.2.3): indices name the elements whose values follow.
  void apply_sparse(const GltfSource& src, const tinygltf::Accessor& acc, std::size_t bytes) {
    const std::string key = key_ + ".sparse";
    const auto n = static_cast<std::size_t>(std::max(acc.sparse.count, 0));
    const std::size_t index_bytes = component_bytes(acc.sparse.indices.componentType);
    if (index_bytes == 0) src.fail(key + ".indices.componentType", "is not an integer type");
    const ByteRange indices = view_bytes(src, acc.sparse.indices.bufferView, key + ".indices");
    const ByteRange values = view_bytes(src, acc.sparse.values.bufferView, key + ".values");
    const auto index_offset = static_cast<std::size_t>(std::max(acc.sparse.indices.byteOffset, 0));
    const auto value_offset = static_cast<std::size_t>(std::max(acc.sparse.values.byteOffset, 0));
    if (index_offset > indices.size || n > (indices.size - index_offset) / index_bytes) {
      src.fail(key + ".indices",
               "its " + std::to_string(n) + " indices do not fit their buffer view");
    }
    const std::size_t element = bytes * components_;
    if (value_offset > values.size || n > (values.size - value_offset) / element) {
      src.fail(key + ".values",
               "its " + std::to_string(n) + " values do not fit their buffer view");
    }
    for (std::size_t k = 0; k < n; ++k) {
      const double i = component(indices.data + index_offset + k * index_bytes,
                                 acc.sparse.indices.componentType, false);
      if (!(i >= 0 && i < static_cast<double>(count()))) {
        src.fail(key + ".indices", "index " + std::to_string(static_cast<long long>(i)) +
                                       " is out of range (" + std::to_string(count()) +
                                       " elements)");
      }
      const unsigned char* at = values.data + value_offset + k * element;
      for (std::size_t c = 0; c < components_; ++c) {
        values_[static_cast<std::size_t>(i) * components_ + c] =
            component(at + c * bytes, acc.componentType, acc.normalized);
      }
    }
  }

  std::string key_;
  std::size_t components_ = 0;
  std::vector<double> values_;
};

const char* primitive_kind(int mode) {
  switch (mode) {
    case TINYGLTF_MODE_POINTS:
      return "point";
    case TINYGLTF_MODE_LINE:
    case TINYGLTF_MODE_LINE_LOOP:
    case TINYGLTF_MODE_LINE_STRIP:
      return "line";
    default:
      return nullptr;
  }
}

// Points and segments a skipped primitive holds, as importers count them.
std::size_t skipped_count(int mode, std::size_t n) {
  switch (mode) {
    case TINYGLTF_MODE_LINE:
      return n / 2;
    case TINYGLTF_MODE_LINE_LOOP:
      return n;
    case TINYGLTF_MODE_LINE_STRIP:
      return n > 0 ? n - 1 : 0;
    default:
      return n;
  }
}

// Triangles a list, strip or fan of \p n corners makes at most.
std::size_t triangle_count(int mode, std::size_t n) {
  if (mode == TINYGLTF_MODE_TRIANGLES) return n / 3;
  return n >= 2 ? n - 2 : 0;
}

/// \brief Places meshes: their triangles, counted once per mesh as the file stores them.
class GltfMeshes {
 public:
  explicit GltfMeshes(const GltfSource& src)
      : src_(src), accessors_(src.model().accessors.size()) {}

  /// Appends mesh \p m placed by \p transform to \p file.
  void place(std::size_t m, const Affine& transform, MeshFile& file) {
    const tinygltf::Mesh& mesh = src_.model().meshes[m];
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
      const std::string key =
          "meshes[" + std::to_string(m) + "].primitives[" + std::to_string(p) + "]";
      place_primitive(mesh.primitives[p], key, transform, file);
    }
  }

  const SkippedItems& skipped() const { return skipped_; }

 private:
  // Decoded once however many primitives and placements share the accessor.
  const AccessorValues& accessor(int index, const std::string& key) {
    const std::size_t a = src_.index(index, accessors_.size(), key);
    if (!accessors_[a]) accessors_[a] = std::make_unique<AccessorValues>(src_, a);
    return *accessors_[a];
  }

  void place_primitive(const tinygltf::Primitive& prim, const std::string& key,
                       const Affine& transform, MeshFile& file) {
    for (const char* compressed : {"KHR_draco_mesh_compression", "EXT_meshopt_compression"}) {
      if (prim.extensions.count(compressed) != 0) {
        src_.fail(key + ".extensions",
                  std::string("uses ") + compressed + ", which shadowkit cannot decode");
      }
    }
    const auto position = prim.attributes.find("POSITION");
    if (position == prim.attributes.end()) {
      src_.fail(key + ".attributes", "has no POSITION");
    }
    const AccessorValues& positions = accessor(position->second, key + ".attributes.POSITION");
    if (positions.components() != 3) src_.fail(positions.key(), "POSITION must be a VEC3");
    std::vector<std::uint32_t> corners(positions.count());
    for (std::size_t i = 0; i < corners.size(); ++i) corners[i] = static_cast<std::uint32_t>(i);
    if (prim.indices >= 0) {
      const AccessorValues& indices = accessor(prim.indices, key + ".indices");
      corners.resize(indices.count());
      for (std::size_t i = 0; i < corners.size(); ++i) {
        const double index = indices.at(i);
        if (!(index >= 0 && index < static_cast<double>(positions.count()))) {
          src_.fail(indices.key(), "index " + format_number(index) +
                                       " is out of range (POSITION has " +
                                       std::to_string(positions.count()) + " elements)");
        }
        corners[i] = static_cast<std::uint32_t>(index);
      }
    }
    const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
    if (const char* kind = primitive_kind(mode)) {
      skipped_.add(std::string(kind) + " primitive(s) (they bound no surface)");
      return;
    }
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        mode != TINYGLTF_MODE_TRIANGLE_FAN) {
      src_.fail(key + ".mode", "unknown primitive mode " + std::to_string(mode));
    }
    if (triangle_count(mode, corners.size()) > limits::kPolygons - file.soup.face_count() ||
        positions.count() > 3 * limits::kPolygons - file.soup.positions.size()) {
      src_.fail(key, "the file places more than " + std::to_string(limits::kPolygons) +
                         " triangles, the most a scene may hold");
    }
    add_triangles(mode, corners, static_cast<std::uint32_t>(file.soup.positions.size()), file.soup);
    for (std::size_t i = 0; i < positions.count(); ++i) {
      const Vec3 p = transform.apply({positions.at(i, 0), positions.at(i, 1), positions.at(i, 2)});
      if (!is_finite(p)) {
        src_.fail(positions.key(), "element " + std::to_string(i) + " is not finite once placed");
      }
      file.soup.positions.push_back(p);
    }
  }

  // Triangles of a list, strip or fan (§3.7.2.1). A strip's triangles alternate their
  // winding back to the strip's; its repeated indices only join runs and make no face.
  static void add_triangles(int mode, const std::vector<std::uint32_t>& c, std::uint32_t base,
                            PolygonSoup& soup) {
    auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t d) {
      if (a != b && b != d && a != d) soup.add_face({base + a, base + b, base + d});
    };
    if (mode == TINYGLTF_MODE_TRIANGLES) {
      for (std::size_t i = 0; i + 2 < c.size(); i += 3) add(c[i], c[i + 1], c[i + 2]);
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
      for (std::size_t i = 0; i + 2 < c.size(); ++i) {
        i % 2 == 0 ? add(c[i], c[i + 1], c[i + 2]) : add(c[i + 1], c[i], c[i + 2]);
      }
    } else {
      for (std::size_t i = 1; i + 1 < c.size(); ++i) add(c[0], c[i], c[i + 1]);
    }
  }

  const GltfSource& src_;
  std::vector<std::unique_ptr<AccessorValues>> accessors_;
  SkippedItems skipped_;
};

// Counts every mesh's primitives once, placed or not, as importers count them: a strip's or
// fan's n corners make n - 2 triangles.
void count_stored(const tinygltf::Model& model, MeshFile& file) {
  for (const tinygltf::Mesh& mesh : model.meshes) {
    for (const tinygltf::Primitive& prim : mesh.primitives) {
      const auto position = prim.attributes.find("POSITION");
      const int a = prim.indices >= 0 ? prim.indices
                                      : (position == prim.attributes.end() ? -1 : position->second);
      if (a < 0 || static_cast<std::size_t>(a) >= model.accessors.size()) continue;
      const std::size_t n = model.accessors[a].count;
      const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
      if (primitive_kind(mode) != nullptr) {
        file.skipped_primitives += skipped_count(mode, n);
      } else {
        file.stored_polygons += triangle_count(mode, n);
      }
    }
  }
}

// The nodes a scene starts from: the default scene's, else the first scene's, else every node
// that is nobody's child (a file without scenes still shows its meshes, as viewers do).
std::vector<std::size_t> root_nodes(const GltfSource& src) {
  const tinygltf::Model& model = src.model();
  std::vector<std::size_t> roots;
  if (!model.scenes.empty()) {
    const std::size_t s =
        model.defaultScene < 0 ? 0 : src.index(model.defaultScene, model.scenes.size(), "scene");
    for (int n : model.scenes[s].nodes) {
      roots.push_back(src.index(n, model.nodes.size(), "scenes[" + std::to_string(s) + "].nodes"));
    }
    return roots;
  }
  std::vector<char> is_child(model.nodes.size(), 0);
  for (const tinygltf::Node& node : model.nodes) {
    for (int child : node.children) {
      if (child >= 0 && static_cast<std::size_t>(child) < is_child.size()) is_child[child] = 1;
    }
  }
  for (std::size_t n = 0; n < model.nodes.size(); ++n) {
    if (!is_child[n]) roots.push_back(n);
  }
  return roots;
}

// Walks the node hierarchy depth first with an explicit stack (files may nest thousands of
// levels) and places every node's mesh. A node that is its own ancestor is an error; a node
// reached by two paths is placed twice, and the polygon limit and a limit on visits bound
// what shared subtrees can multiply.
void place_nodes(const GltfSource& src, GltfMeshes& meshes, MeshFile& file) {
  const tinygltf::Model& model = src.model();
  struct Visit {
    std::size_t node;
    std::size_t parent_node;  // for messages; a root's is its own
    Affine parent;
    bool leaving;
  };
  std::vector<char> on_path(model.nodes.size(), 0);
  std::vector<Visit> stack;
  const std::vector<std::size_t> roots = root_nodes(src);
  for (std::size_t r = roots.size(); r-- > 0;) stack.push_back({roots[r], roots[r], {}, false});
  std::size_t visits = 0;
  while (!stack.empty()) {
    const Visit visit = stack.back();
    stack.pop_back();
    if (visit.leaving) {
      on_path[visit.node] = 0;
      continue;
    }
    const std::string key = "nodes[" + std::to_string(visit.node) + "]";
    if (on_path[visit.node]) {
      src.fail("nodes[" + std::to_string(visit.parent_node) + "].children",
               "names node " + std::to_string(visit.node) + ", its own ancestor");
    }
    if (++visits > limits::kPolygons) {
      src.fail(key, "the node hierarchy places nodes more than " +
                        std::to_string(limits::kPolygons) + " times");
    }
    on_path[visit.node] = 1;
    const tinygltf::Node& node = model.nodes[visit.node];
    const Affine world = visit.parent * local_transform(node, src, visit.node);
    if (node.mesh >= 0)
      meshes.place(src.index(node.mesh, model.meshes.size(), key + ".mesh"), world, file);
    stack.push_back({visit.node, visit.node, {}, true});
    for (std::size_t c = node.children.size(); c-- > 0;) {
      stack.push_back({src.index(node.children[c], model.nodes.size(), key + ".children"),
                       visit.node, world, false});
    }
  }
}

// Files tinygltf may open: only those the glTF names, read by us with errors we word.
bool read_referenced_file(std::vector<unsigned char>* out, std::string* err,
                          const std::string& path, void* /*user*/) {
  if (const std::string why = why_not_a_file(path); !why.empty()) {
    *err += why;
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    *err += "cannot open '" + path + "'";
    return false;
  }
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    out->insert(out->end(), buffer, buffer + in.gcount());
  }
  return !in.bad();
}

bool file_exists(const std::string& path, void* /*user*/) {
  return std::ifstream(path).good();
}

// tinygltf would expand '~' and environment variables in URIs: a file's URI is taken as it
// is written.
std::string unexpanded(const std::string& path, void* /*user*/) {
  return path;
}

bool refuse_write(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  *err = "writing is not allowed";
  return false;
}

// Images do not shadow: they are neither decoded nor checked.
bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                const unsigned char*, int, void*) {
  return true;
}

// Parses \p data into \p model; false with tinygltf's first line of error when it cannot.
bool parse_model(std::string_view data, const std::string& path, tinygltf::Model& model,
                 std::string& error) {
  constexpr std::string_view kGlbMagic = "glTF";
  const bool binary = data.starts_with(kGlbMagic);
  if (binary) {
    // The JSON chunk begins after the 12-byte header and an 8-byte chunk header.
    if (data.size() >= 20) {
      const auto json_length =
          load<std::uint32_t>(reinterpret_cast<const unsigned char*>(data.data()) + 12);
      check_json_depth(data.substr(20, json_length), path + " (JSON chunk)");
    }
  } else {
    check_json_depth(data, path);
  }
  if (data.size() > std::numeric_limits<unsigned int>::max()) {
    throw InputError(path, "glTF files over 4 GiB are not supported");
  }
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&skip_image, nullptr);
  loader.SetFsCallbacks({&file_exists, &unexpanded, &read_referenced_file, &refuse_write, nullptr});
  std::string warning;
  const std::string base_dir = std::filesystem::path(path).parent_path().string();
  const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
  const auto size = static_cast<unsigned int>(data.size());
  const bool ok =
      binary ? loader.LoadBinaryFromMemory(&model, &error, &warning, bytes, size, base_dir)
             : loader.LoadASCIIFromString(&model, &error, &warning, data.data(), size, base_dir);
  if (ok) return true;
  // tinygltf's messages may run over several lines: the first says what is wrong.
  error = error.empty() ? "tinygltf could not read it" : first_line(error);
  return false;
}

}  // namespace

MeshFile read_gltf(std::string_view data, const std::string& path, const Context& ctx) {
  tinygltf::Model model;
  std::string error;
  if (!parse_model(data, path, model, error) || model.asset.version.starts_with("1")) {
    // glTF 1.0, and buffers tinygltf cannot decode (Draco), may still be assimp's to read.
    try {
      return read_with_assimp(path, ctx);
    } catch (const InputError&) {
      if (error.empty()) throw;
      throw InputError(path, "not a valid glTF 2.0 file: " + error);
    }
  }
  const GltfSource src(model, path);
  MeshFile file;
  GltfMeshes meshes(src);
  place_nodes(src, meshes, file);
  count_stored(model, file);
  meshes.skipped().warn(path, ctx);
  return file;
}

}  // namespace shadowkit::mesh_io
