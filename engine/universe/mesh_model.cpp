// Mesh files: glTF 2.0 through tinygltf, Wavefront OBJ through tinyobjloader
// (both Debian packages; small readers of exactly the two formats the engine
// takes, where assimp would bring forty). Whatever the format, the triangles
// then go through one check: welded at equal positions, grouped by material,
// refused when degenerate or non-manifold, closed pieces oriented outward.
#include "universe/mesh_model.hpp"

#include <sys/stat.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <numeric>
#include <unordered_map>

#include <tiny_gltf.h>
#include <tiny_obj_loader.h>

#include "core/error.hpp"
#include "core/read_file.hpp"

namespace eoir::universe {
namespace {

// Triangles as a file gives them, before the check.
struct RawMesh {
  std::vector<Eigen::Vector3d> positions;
  std::vector<std::array<std::int64_t, 3>> triangles;
  std::vector<std::string> triangle_material;  // per triangle
};

struct MeshFileError {
  Status status;
  std::string problem;
};
[[noreturn]] void problem(const std::string& what, Status status = Status::corrupt_file) {
  throw MeshFileError{status, what};
}

void check_count(std::size_t triangles) {
  if (triangles > max_mesh_triangles)
    problem("more than " + std::to_string(max_mesh_triangles) + " triangles (the limit of a mesh)",
            Status::limit_exceeded);
}

// tinyobjloader reads a vertex coordinate it cannot parse ("nan", "1e999",
// a word) as 0, and a `usemtl` name without a .mtl file as no material:
// every "v" line is checked here first, so that a corrupt vertex is refused
// rather than moved, and each face's material is taken from its `usemtl`
// line (the triangles of a face of n vertices: n - 2, in file order).
std::vector<std::string> scan_obj(const std::string& path) {
  std::ifstream in(path);
  std::string line, material;
  std::vector<std::string> triangle_material;
  std::size_t vertex = 0;
  while (std::getline(in, line)) {
    if (line.rfind("usemtl", 0) == 0 && line.size() > 6 && std::isspace(static_cast<unsigned char>(line[6]))) {
      const std::size_t a = line.find_first_not_of(" \t", 6), b = line.find_last_not_of(" \t\r");
      material = a == std::string::npos ? "" : line.substr(a, b - a + 1);
      continue;
    }
    if (line.size() < 2 || (line[1] != ' ' && line[1] != '\t')) continue;
    if (line[0] == 'f') {
      std::size_t tokens = 0;
      for (std::size_t i = 1; i < line.size();) {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        if (i < line.size()) ++tokens;
        while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
      }
      for (std::size_t k = 2; k < tokens; ++k) triangle_material.push_back(material);
      continue;
    }
    if (line[0] != 'v') continue;
    const char* p = line.c_str() + 1;
    for (int k = 0; k < 3; ++k) {
      char* end = nullptr;
      const double x = std::strtod(p, &end);
      if (end == p || !std::isfinite(x) || (*end && !std::isspace(static_cast<unsigned char>(*end))))
        problem("vertex " + std::to_string(vertex) + " is not finite (coordinate " + std::to_string(k) + " of '" + line + "')");
      p = end;
    }
    ++vertex;
  }
  return triangle_material;
}

RawMesh read_obj(const std::string& path) {
  const std::vector<std::string> usemtl = scan_obj(path);
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  config.mtl_search_path = std::filesystem::path(path).parent_path().string();
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(path, config)) problem("not a readable OBJ file (" + reader.Error() + ")");
  RawMesh m;
  const auto& v = reader.GetAttrib().vertices;
  for (std::size_t i = 0; i + 2 < v.size(); i += 3) m.positions.emplace_back(v[i], v[i + 1], v[i + 2]);
  const auto& materials = reader.GetMaterials();
  std::size_t total = 0;
  for (const auto& shape : reader.GetShapes()) total += shape.mesh.num_face_vertices.size();
  check_count(total);
  const bool by_usemtl = usemtl.size() == total;  // (else a face our scan read otherwise: the reader's ids)
  for (const auto& shape : reader.GetShapes()) {
    const auto& mesh = shape.mesh;
    std::size_t index = 0;
    for (std::size_t f = 0; f < mesh.num_face_vertices.size(); ++f) {
      const std::size_t n = mesh.num_face_vertices[f];
      if (n != 3) problem("face " + std::to_string(f) + " of '" + shape.name + "' has " + std::to_string(n) + " vertices after triangulation");
      std::array<std::int64_t, 3> tri{};
      for (std::size_t k = 0; k < 3; ++k) tri[k] = mesh.indices[index + k].vertex_index;
      index += n;
      m.triangles.push_back(tri);
      const int id = f < mesh.material_ids.size() ? mesh.material_ids[f] : -1;
      m.triangle_material.push_back(by_usemtl ? usemtl[m.triangles.size() - 1]
                                    : id >= 0 && static_cast<std::size_t>(id) < materials.size() ? materials[id].name
                                                                                                  : "");
    }
  }
  return m;
}

// glTF: ignore images (the engine takes materials by name, not textures).
bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
  return true;
}

// The bytes of element i of an accessor, bounds-checked.
const unsigned char* element(const tinygltf::Model& model, const tinygltf::Accessor& a, std::size_t i,
                             std::size_t element_bytes, const std::string& what) {
  if (a.sparse.isSparse) problem(what + ": sparse accessors are not read");
  if (a.bufferView < 0 || static_cast<std::size_t>(a.bufferView) >= model.bufferViews.size())
    problem(what + ": accessor without a buffer view");
  const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(a.bufferView)];
  if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size()) problem(what + ": no buffer");
  const std::vector<unsigned char>& data = model.buffers[static_cast<std::size_t>(view.buffer)].data;
  const std::size_t stride = view.byteStride ? view.byteStride : element_bytes;
  const std::size_t offset = view.byteOffset + a.byteOffset + i * stride;
  if (offset + element_bytes > view.byteOffset + view.byteLength || offset + element_bytes > data.size())
    problem(what + ": accessor reads past its buffer");
  return data.data() + offset;
}

void add_gltf_mesh(const tinygltf::Model& model, int mesh_index, const Eigen::Matrix4d& transform, RawMesh& out) {
  if (mesh_index < 0 || static_cast<std::size_t>(mesh_index) >= model.meshes.size()) problem("a node names no mesh");
  const tinygltf::Mesh& mesh = model.meshes[static_cast<std::size_t>(mesh_index)];
  for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
    const tinygltf::Primitive& prim = mesh.primitives[p];
    const std::string what = "mesh '" + mesh.name + "' primitive " + std::to_string(p);
    if (prim.mode != -1 && prim.mode != TINYGLTF_MODE_TRIANGLES)
      problem(what + ": mode " + std::to_string(prim.mode) + " (only triangles are read)");
    const auto pos = prim.attributes.find("POSITION");
    if (pos == prim.attributes.end()) problem(what + ": no POSITION");
    if (pos->second < 0 || static_cast<std::size_t>(pos->second) >= model.accessors.size()) problem(what + ": bad POSITION");
    const tinygltf::Accessor& pa = model.accessors[static_cast<std::size_t>(pos->second)];
    if (pa.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || pa.type != TINYGLTF_TYPE_VEC3)
      problem(what + ": POSITION is not float VEC3");
    const std::int64_t base = static_cast<std::int64_t>(out.positions.size());
    for (std::size_t i = 0; i < pa.count; ++i) {
      float xyz[3];
      std::memcpy(xyz, element(model, pa, i, sizeof xyz, what + " POSITION"), sizeof xyz);
      const Eigen::Vector4d h = transform * Eigen::Vector4d(xyz[0], xyz[1], xyz[2], 1.0);
      out.positions.emplace_back(h.x(), h.y(), h.z());
    }
    std::vector<std::int64_t> indices;
    if (prim.indices >= 0) {
      if (static_cast<std::size_t>(prim.indices) >= model.accessors.size()) problem(what + ": bad indices");
      const tinygltf::Accessor& ia = model.accessors[static_cast<std::size_t>(prim.indices)];
      if (ia.type != TINYGLTF_TYPE_SCALAR) problem(what + ": indices are not scalars");
      check_count(ia.count / 3);
      for (std::size_t i = 0; i < ia.count; ++i) {
        switch (ia.componentType) {
          case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: indices.push_back(*element(model, ia, i, 1, what)); break;
          case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t x;
            std::memcpy(&x, element(model, ia, i, 2, what), 2);
            indices.push_back(x);
            break;
          }
          case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            std::uint32_t x;
            std::memcpy(&x, element(model, ia, i, 4, what), 4);
            indices.push_back(x);
            break;
          }
          default: problem(what + ": indices of component type " + std::to_string(ia.componentType));
        }
      }
    } else {
      indices.resize(pa.count);
      std::iota(indices.begin(), indices.end(), 0);
    }
    if (indices.size() % 3) problem(what + ": " + std::to_string(indices.size()) + " indices, not triangles");
    std::string material;
    if (prim.material >= 0 && static_cast<std::size_t>(prim.material) < model.materials.size()) {
      material = model.materials[static_cast<std::size_t>(prim.material)].name;
      if (material.empty()) material = "material_" + std::to_string(prim.material);
    }
    for (std::size_t i = 0; i < indices.size(); i += 3) {
      std::array<std::int64_t, 3> tri{};
      for (std::size_t k = 0; k < 3; ++k) {
        if (indices[i + k] >= static_cast<std::int64_t>(pa.count)) problem(what + ": index beyond its positions");
        tri[k] = base + indices[i + k];
      }
      out.triangles.push_back(tri);
      out.triangle_material.push_back(material);
    }
    check_count(out.triangles.size());
  }
}

Eigen::Matrix4d node_matrix(const tinygltf::Node& node) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  if (node.matrix.size() == 16) {
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) m(r, c) = node.matrix[static_cast<std::size_t>(4 * c + r)];  // column-major
    return m;
  }
  Eigen::Matrix4d t = Eigen::Matrix4d::Identity(), r = t, s = t;
  if (node.translation.size() == 3) t.block<3, 1>(0, 3) = Eigen::Vector3d(node.translation[0], node.translation[1], node.translation[2]);
  if (node.rotation.size() == 4)  // x, y, z, w
    r.block<3, 3>(0, 0) =
        Eigen::Quaterniond(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]).normalized().toRotationMatrix();
  if (node.scale.size() == 3) s.diagonal().head<3>() = Eigen::Vector3d(node.scale[0], node.scale[1], node.scale[2]);
  return t * r * s;
}

void add_gltf_node(const tinygltf::Model& model, int index, const Eigen::Matrix4d& parent, int depth, RawMesh& out) {
  if (index < 0 || static_cast<std::size_t>(index) >= model.nodes.size()) problem("a scene names no node");
  if (depth > 64) problem("nodes nest more than 64 deep (a cycle?)");
  const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(index)];
  const Eigen::Matrix4d m = parent * node_matrix(node);
  if (node.mesh >= 0) add_gltf_mesh(model, node.mesh, m, out);
  for (int child : node.children) add_gltf_node(model, child, m, depth + 1, out);
}

RawMesh read_gltf(const std::string& path, bool binary) {
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(skip_image, nullptr);
  std::string err, warn;
  const bool ok = binary ? loader.LoadBinaryFromFile(&model, &err, &warn, path)
                         : loader.LoadASCIIFromFile(&model, &err, &warn, path);
  if (!ok) problem("not a readable glTF file (" + err + ")");
  RawMesh m;
  if (model.scenes.empty()) {
    for (std::size_t i = 0; i < model.meshes.size(); ++i) add_gltf_mesh(model, static_cast<int>(i), Eigen::Matrix4d::Identity(), m);
  } else {
    const int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
    if (static_cast<std::size_t>(scene) >= model.scenes.size()) problem("the default scene does not exist");
    for (int node : model.scenes[static_cast<std::size_t>(scene)].nodes)
      add_gltf_node(model, node, Eigen::Matrix4d::Identity(), 0, m);
  }
  return m;
}

// The check and orientation every file's triangles go through.
MeshModel build(const std::string& file, const RawMesh& raw) {
  if (raw.triangles.empty()) problem("no triangles");
  check_count(raw.triangles.size());
  MeshModel m;
  m.file = file;
  // Weld equal positions (a glTF repeats a vertex for each normal or texture
  // coordinate): the edges shared by index are then the shared edges.
  struct Key {
    double x, y, z;
    bool operator==(const Key& o) const { return x == o.x && y == o.y && z == o.z; }
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      std::uint64_t h = 1469598103934665603ull;
      for (double v : {k.x, k.y, k.z}) {
        std::uint64_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        h = (h ^ bits) * 1099511628211ull;
      }
      return static_cast<std::size_t>(h);
    }
  };
  std::unordered_map<Key, std::int32_t, KeyHash> welded;
  std::vector<std::int32_t> remap(raw.positions.size(), -1);
  const auto vertex = [&](std::int64_t i, std::size_t triangle) -> std::int32_t {
    if (i < 0 || static_cast<std::size_t>(i) >= raw.positions.size())
      problem("triangle " + std::to_string(triangle) + " names vertex " + std::to_string(i) + ", which does not exist");
    std::int32_t& r = remap[static_cast<std::size_t>(i)];
    if (r >= 0) return r;
    const Eigen::Vector3d& p = raw.positions[static_cast<std::size_t>(i)];
    if (!p.allFinite()) problem("vertex " + std::to_string(i) + " is not finite");
    const Key key{p.x() + 0.0, p.y() + 0.0, p.z() + 0.0};  // (+0.0: -0 welds with 0)
    auto [it, added] = welded.emplace(key, static_cast<std::int32_t>(m.vertices.size()));
    if (added) m.vertices.push_back(p);
    return r = it->second;
  };
  std::map<std::string, std::int32_t> groups;
  for (std::size_t t = 0; t < raw.triangles.size(); ++t) {
    std::array<std::int32_t, 3> tri{};
    for (std::size_t k = 0; k < 3; ++k) tri[k] = vertex(raw.triangles[t][k], t);
    const Eigen::Vector3d e1 = m.vertices[tri[1]] - m.vertices[tri[0]], e2 = m.vertices[tri[2]] - m.vertices[tri[0]];
    const double scale2 = std::max(e1.squaredNorm(), e2.squaredNorm());
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2] || !(e1.cross(e2).norm() > 1e-12 * scale2))
      problem("triangle " + std::to_string(t) + " is degenerate (zero area)");
    m.triangles.push_back(tri);
    const std::string& material = raw.triangle_material[t];
    auto [it, added] = groups.emplace(material, static_cast<std::int32_t>(m.group_materials.size()));
    if (added) m.group_materials.push_back(material);
    if (m.group_materials.size() > max_mesh_materials)
      problem("more than " + std::to_string(max_mesh_materials) + " materials (the limit of a mesh)", Status::limit_exceeded);
    m.triangle_group.push_back(it->second);
  }
  // Edges: each undirected edge with the triangles on it and their direction.
  const std::size_t n = m.triangles.size();
  struct EdgeUse {
    std::uint64_t key;
    std::int32_t triangle;
    bool forward;  // the triangle runs low -> high vertex along it
  };
  std::vector<EdgeUse> uses;
  uses.reserve(3 * n);
  for (std::size_t t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k) {
      const std::int32_t a = m.triangles[t][k], b = m.triangles[t][(k + 1) % 3];
      const std::uint64_t lo = static_cast<std::uint64_t>(std::min(a, b)), hi = static_cast<std::uint64_t>(std::max(a, b));
      uses.push_back(EdgeUse{(lo << 32) | hi, static_cast<std::int32_t>(t), a < b});
    }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) { return x.key < y.key; });
  std::vector<std::int32_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](std::int32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::vector<std::uint8_t> open(n, 0);
  std::vector<std::vector<std::pair<std::int32_t, bool>>> neighbours(n);  // (triangle, same direction on the edge)
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].key == uses[i].key) ++j;
    if (j - i > 2)
      problem("the edge between vertices " + std::to_string(uses[i].key >> 32) + " and " +
              std::to_string(uses[i].key & 0xffffffffu) + " is shared by " + std::to_string(j - i) +
              " triangles (non-manifold)");
    if (j - i == 1) {
      open[uses[i].triangle] = 1;
    } else {
      const EdgeUse &x = uses[i], &y = uses[i + 1];
      parent[root(x.triangle)] = root(y.triangle);
      neighbours[x.triangle].push_back({y.triangle, x.forward == y.forward});
      neighbours[y.triangle].push_back({x.triangle, x.forward == y.forward});
    }
    i = j;
  }
  // Pieces: closed where no triangle has an open edge.
  std::vector<std::uint8_t> piece_open(n, 0);
  for (std::size_t t = 0; t < n; ++t)
    if (open[t]) piece_open[root(static_cast<std::int32_t>(t))] = 1;
  // Orient each closed piece consistently (across every edge the two
  // triangles run opposite ways), then outward (positive volume).
  std::vector<std::int8_t> flip(n, -1);
  std::vector<double> piece_volume(n, 0.0);
  std::vector<std::int32_t> stack;
  for (std::size_t s = 0; s < n; ++s) {
    if (flip[s] >= 0 || piece_open[root(static_cast<std::int32_t>(s))]) continue;
    flip[s] = 0;
    stack.assign(1, static_cast<std::int32_t>(s));
    while (!stack.empty()) {
      const std::int32_t t = stack.back();
      stack.pop_back();
      for (const auto& [u, same] : neighbours[t]) {
        const std::int8_t want = static_cast<std::int8_t>(same ? !flip[t] : flip[t]);
        if (flip[u] < 0) {
          flip[u] = want;
          stack.push_back(u);
        } else if (flip[u] != want) {
          problem("the watertight piece holding triangle " + std::to_string(t) + " cannot be oriented (non-orientable)");
        }
      }
    }
  }
  for (std::size_t t = 0; t < n; ++t) {
    if (flip[t] == 1) std::swap(m.triangles[t][1], m.triangles[t][2]);
    if (flip[t] < 0) continue;
    const auto& tri = m.triangles[t];
    piece_volume[root(static_cast<std::int32_t>(t))] +=
        m.vertices[tri[0]].dot(m.vertices[tri[1]].cross(m.vertices[tri[2]])) / 6.0;
  }
  m.closed = true;
  m.triangle_closed.assign(n, 0);
  for (std::size_t t = 0; t < n; ++t) {
    const std::int32_t r = root(static_cast<std::int32_t>(t));
    if (piece_open[r]) {
      m.closed = false;
      continue;
    }
    m.triangle_closed[t] = 1;
    if (piece_volume[r] < 0) std::swap(m.triangles[t][1], m.triangles[t][2]);
  }
  for (std::size_t r = 0; r < n; ++r)
    if (static_cast<std::size_t>(root(static_cast<std::int32_t>(r))) == r && !piece_open[r])
      m.volume += std::fabs(piece_volume[r]);
  return m;
}

std::string extension(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

struct CacheEntry {
  std::int64_t size = 0, mtime_ns = 0;
  std::weak_ptr<const MeshModel> model;
};

}  // namespace

std::shared_ptr<const MeshModel> load_mesh(const std::string& path, const std::string& field) {
  const std::string where = field + ": mesh file '" + path + "'";
  if (path.empty()) throw Error(Status::out_of_range, field + ": empty (name a .gltf, .glb or .obj file)");
  const std::string ext = extension(path);
  if (ext != ".gltf" && ext != ".glb" && ext != ".obj")
    throw Error(Status::out_of_range, where + ": unknown format '" + ext + "' (.gltf, .glb or .obj)");
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) throw Error(Status::io, where + ": " + std::strerror(errno));
  try {
    require_regular_file(path, st.st_mode);
  } catch (const Error& e) {
    throw Error(e.status(), field + ": " + e.what());
  }
  if (static_cast<std::uint64_t>(st.st_size) > max_mesh_file_bytes)
    throw Error(Status::limit_exceeded, where + ": larger than " + std::to_string(max_mesh_file_bytes >> 20) +
                                            " MiB, the limit of a mesh file");
  const std::int64_t mtime_ns = static_cast<std::int64_t>(st.st_mtim.tv_sec) * 1000000000 + st.st_mtim.tv_nsec;
  static std::mutex mutex;
  static std::map<std::string, CacheEntry> cache;
  {
    std::lock_guard<std::mutex> lock(mutex);
    auto it = cache.find(path);
    if (it != cache.end() && it->second.size == st.st_size && it->second.mtime_ns == mtime_ns)
      if (auto model = it->second.model.lock()) return model;
  }
  std::shared_ptr<const MeshModel> model;
  try {
    const RawMesh raw = ext == ".obj" ? read_obj(path) : read_gltf(path, ext == ".glb");
    model = std::make_shared<const MeshModel>(build(path, raw));
  } catch (const MeshFileError& e) {
    throw Error(e.status, where + ": " + e.problem);
  } catch (const std::bad_alloc&) {
    throw Error(Status::limit_exceeded, where + ": too large to hold in memory");
  }
  std::lock_guard<std::mutex> lock(mutex);
  cache[path] = CacheEntry{st.st_size, mtime_ns, model};
  return model;
}

}  // namespace eoir::universe
