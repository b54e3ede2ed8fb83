// Mesh files written by the tests themselves (independent of the engine's
// readers): an icosphere (the icosahedron's faces split in four, `levels`
// times, vertices pushed onto the unit sphere: 20 * 4^levels triangles), a
// unit cube, and the same cube as glTF 2.0 with its buffer embedded.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace eoir::test {

struct TriangleMesh {
  std::vector<std::array<double, 3>> vertices;
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise seen from outside
};

inline TriangleMesh icosphere(int levels) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  TriangleMesh m;
  for (const auto& v : std::vector<std::array<double, 3>>{{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                                         {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                                         {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}}) {
    const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    m.vertices.push_back({v[0] / n, v[1] / n, v[2] / n});
  }
  m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> middle;
    const auto mid = [&](int a, int b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = middle.find(key);
      if (it != middle.end()) return it->second;
      std::array<double, 3> p{};
      for (int k = 0; k < 3; ++k) p[k] = 0.5 * (m.vertices[a][k] + m.vertices[b][k]);
      const double n = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
      m.vertices.push_back({p[0] / n, p[1] / n, p[2] / n});
      return middle[key] = static_cast<int>(m.vertices.size()) - 1;
    };
    std::vector<std::array<int, 3>> next;
    for (const auto& f : m.triangles) {
      const int a = mid(f[0], f[1]), b = mid(f[1], f[2]), c = mid(f[2], f[0]);
      next.insert(next.end(), {{f[0], a, c}, {f[1], b, a}, {f[2], c, b}, {a, b, c}});
    }
    m.triangles = std::move(next);
  }
  return m;
}

// The cube [-0.5, 0.5]^3 as 12 triangles.
inline TriangleMesh unit_cube() {
  TriangleMesh m;
  for (int i = 0; i < 8; ++i) m.vertices.push_back({(i & 1) - 0.5, ((i >> 1) & 1) - 0.5, ((i >> 2) & 1) - 0.5});
  m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

// The same cube with each face cut into n x n squares of two triangles
// (12 n^2 triangles; vertices on shared edges at equal positions).
inline TriangleMesh subdivided_cube(int n) {
  TriangleMesh m;
  const auto coordinate = [n](int i) { return static_cast<double>(i) / n - 0.5; };
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      const int base = static_cast<int>(m.vertices.size());
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
          std::array<double, 3> p{};
          p[axis] = side ? 0.5 : -0.5;
          p[u] = coordinate(i);
          p[v] = coordinate(j);
          m.vertices.push_back(p);
        }
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const int a = base + j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
          // (u x v = +axis: counter-clockwise from outside on the + side)
          if (side)
            m.triangles.insert(m.triangles.end(), {{a, b, d}, {a, d, c}});
          else
            m.triangles.insert(m.triangles.end(), {{a, d, b}, {a, c, d}});
        }
    }
  return m;
}

// Wavefront OBJ; `material` (optional) names a usemtl for every face.
inline void write_obj(const std::string& path, const TriangleMesh& m, const std::string& material = "") {
  std::ofstream out(path);
  out.precision(17);
  for (const auto& v : m.vertices) out << "v " << v[0] << ' ' << v[1] << ' ' << v[2] << '\n';
  if (!material.empty()) out << "usemtl " << material << '\n';
  for (const auto& f : m.triangles) out << "f " << f[0] + 1 << ' ' << f[1] + 1 << ' ' << f[2] + 1 << '\n';
}

// glTF 2.0 (.gltf, JSON) with its one buffer as a base64 data URI: float
// positions, uint32 indices, one mesh in one node of one scene.
inline void write_gltf(const std::string& path, const TriangleMesh& m) {
  std::vector<unsigned char> bytes;
  const auto put = [&](const void* p, std::size_t n) {
    const auto* c = static_cast<const unsigned char*>(p);
    bytes.insert(bytes.end(), c, c + n);
  };
  float lo[3] = {1e30f, 1e30f, 1e30f}, hi[3] = {-1e30f, -1e30f, -1e30f};
  for (const auto& v : m.vertices)
    for (int k = 0; k < 3; ++k) {
      const float x = static_cast<float>(v[k]);
      put(&x, 4);
      lo[k] = std::min(lo[k], x);
      hi[k] = std::max(hi[k], x);
    }
  const std::size_t position_bytes = bytes.size();
  for (const auto& f : m.triangles)
    for (int k = 0; k < 3; ++k) {
      const auto i = static_cast<std::uint32_t>(f[k]);
      put(&i, 4);
    }
  static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string b64;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::uint32_t n = (bytes[i] << 16) | ((i + 1 < bytes.size() ? bytes[i + 1] : 0) << 8) |
                            (i + 2 < bytes.size() ? bytes[i + 2] : 0);
    b64 += alphabet[(n >> 18) & 63];
    b64 += alphabet[(n >> 12) & 63];
    b64 += i + 1 < bytes.size() ? alphabet[(n >> 6) & 63] : '=';
    b64 += i + 2 < bytes.size() ? alphabet[n & 63] : '=';
  }
  std::ofstream out(path);
  out << "{\"asset\": {\"version\": \"2.0\"}, \"scene\": 0, \"scenes\": [{\"nodes\": [0]}], \"nodes\": [{\"mesh\": 0}],\n"
      << " \"meshes\": [{\"primitives\": [{\"attributes\": {\"POSITION\": 0}, \"indices\": 1, \"material\": 0}]}],\n"
      << " \"materials\": [{\"name\": \"hull\"}],\n"
      << " \"accessors\": [{\"bufferView\": 0, \"componentType\": 5126, \"count\": " << m.vertices.size()
      << ", \"type\": \"VEC3\", \"min\": [" << lo[0] << ',' << lo[1] << ',' << lo[2] << "], \"max\": [" << hi[0] << ','
      << hi[1] << ',' << hi[2] << "]},\n"
      << "   {\"bufferView\": 1, \"componentType\": 5125, \"count\": " << 3 * m.triangles.size()
      << ", \"type\": \"SCALAR\"}],\n"
      << " \"bufferViews\": [{\"buffer\": 0, \"byteOffset\": 0, \"byteLength\": " << position_bytes << "},\n"
      << "   {\"buffer\": 0, \"byteOffset\": " << position_bytes << ", \"byteLength\": " << bytes.size() - position_bytes
      << "}],\n"
      << " \"buffers\": [{\"byteLength\": " << bytes.size() << ", \"uri\": \"data:application/octet-stream;base64,"
      << b64 << "\"}]}\n";
}

}  // namespace eoir::test
