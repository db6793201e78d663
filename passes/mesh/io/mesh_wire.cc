#include "passes/mesh/io/mesh_wire.h"

#include <fmt/format.h>

#include <cstdint>
#include <cstring>
#include <optional>

namespace mdlc::mesh {
namespace {

constexpr std::string_view kMagic = "MDLCMESH";
enum : uint8_t { kMeshReply = 0, kErrorReply = 1 };

template <typename T>
void Put(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof(T));
}

/// Reads fixed-size values off the front of the reply; fails (false) rather
/// than read past its end.
class Reader {
 public:
  explicit Reader(std::string_view bytes) : rest_(bytes) {}
  template <typename T>
  bool Get(T& value) {
    if (rest_.size() < sizeof(T)) return false;
    std::memcpy(&value, rest_.data(), sizeof(T));
    rest_.remove_prefix(sizeof(T));
    return true;
  }
  /// Whether `count` items of `size` bytes are left (without overflowing).
  bool Holds(uint64_t count, size_t size) const { return count <= rest_.size() / size; }
  std::string_view Take(size_t n) {
    std::string_view taken = rest_.substr(0, n);
    rest_.remove_prefix(n);
    return taken;
  }
  size_t left() const { return rest_.size(); }

 private:
  std::string_view rest_;
};

std::optional<MeshOrError> Fail(std::string* problem, std::string message) {
  *problem = std::move(message);
  return std::nullopt;
}

constexpr std::string_view kColladaUpAxis = "collada-up-axis=";

/// The colour runs that end a mesh reply: what is wrong with them, if
/// anything (a count that is not what is left, runs out of order or past the
/// triangles, a channel outside [0, 1]).
std::optional<std::string> DecodeColors(Reader& in, uint64_t triangles,
                                        std::vector<TriangleColor>& colors) {
  constexpr size_t kRunBytes = sizeof(uint64_t) + 4 * sizeof(double);
  uint64_t count = 0;
  if (!in.Get(count) || !in.Holds(count, kRunBytes) || count * kRunBytes != in.left()) {
    return "its size does not match its vertices, triangles and colours";
  }
  colors.resize(count);
  for (uint64_t i = 0; i < count; ++i) {
    TriangleColor& c = colors[i];
    in.Get(c.first_triangle);
    for (int k = 0; k < 4; ++k) in.Get(c.rgba[k]);
    const bool ordered = i == 0 ? c.first_triangle == 0
                                : c.first_triangle > colors[i - 1].first_triangle;
    if (!ordered || c.first_triangle >= triangles) {
      return fmt::format("its colour run {} starts at triangle {} of {}", i, c.first_triangle,
                         triangles);
    }
    if (!(c.rgba.minCoeff() >= 0 && c.rgba.maxCoeff() <= 1)) {
      return fmt::format("its colour run {} has a channel outside [0, 1]", i);
    }
  }
  return std::nullopt;
}

}  // namespace

std::vector<std::string> EncodeMeshSettings(const Limits& limits, const MeshAxes& axes) {
  std::vector<std::string> args;
  for (const LimitInfo& l : AllLimits()) {
    args.push_back(fmt::format("{}={}", l.name, limits.*l.field));
  }
  args.push_back(fmt::format("{}{}", kColladaUpAxis, ColladaUpAxisName(axes.collada)));
  return args;
}

std::vector<std::string> EncodeMeshRequest(const std::string& path, const Limits& limits,
                                           const MeshAxes& axes) {
  std::vector<std::string> args = EncodeMeshSettings(limits, axes);
  args.push_back("--");
  args.push_back(path);
  return args;
}

std::optional<std::string> DecodeMeshRequest(const std::vector<std::string_view>& args,
                                             std::string* path, Limits* limits, MeshAxes* axes) {
  size_t i = 0;
  for (; i < args.size() && args[i] != "--"; ++i) {
    if (args[i].starts_with(kColladaUpAxis)) {
      const std::string_view mode = args[i].substr(kColladaUpAxis.size());
      auto collada = ColladaUpAxisFromName(mode);
      if (!collada) return fmt::format("unknown collada-up-axis '{}'", mode);
      axes->collada = *collada;
      continue;
    }
    if (auto problem = SetLimit(*limits, args[i])) return problem;
  }
  if (i + 2 != args.size()) return "expected one mesh file after '--'";
  *path = std::string(args[i + 1]);
  return std::nullopt;
}

std::string EncodeMeshReply(const MeshOrError& result) {
  std::string out(kMagic);
  Put(out, kMeshWireVersion);
  if (!result.ok()) {
    Put(out, uint8_t{kErrorReply});
    Put(out, uint8_t{result.over_limit});
    Put(out, uint64_t{result.error.size()});
    out += result.error;
    return out;
  }
  const TriangleMesh& m = *result.mesh;
  Put(out, uint8_t{kMeshReply});
  Put(out, static_cast<uint8_t>(m.declared_up));
  Put(out, uint8_t{m.turned_to_z_up});
  Put(out, uint64_t{m.vertices.size()});
  Put(out, uint64_t{m.triangles.size()});
  // Eigen's fixed-size vectors are their coefficients, packed: the two
  // arrays go out as they lie in memory
  static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double));
  static_assert(sizeof(Eigen::Vector3i) == 3 * sizeof(int32_t));
  out.append(reinterpret_cast<const char*>(m.vertices.data()),
             m.vertices.size() * sizeof(Eigen::Vector3d));
  out.append(reinterpret_cast<const char*>(m.triangles.data()),
             m.triangles.size() * sizeof(Eigen::Vector3i));
  Put(out, uint64_t{m.colors.size()});
  for (const TriangleColor& c : m.colors) {
    Put(out, c.first_triangle);
    for (int k = 0; k < 4; ++k) Put(out, c.rgba[k]);
  }
  return out;
}

std::optional<MeshOrError> DecodeMeshReply(std::string_view bytes, std::string* problem) {
  if (!bytes.starts_with(kMagic)) return Fail(problem, "it does not start with the reply marker");
  Reader in(bytes.substr(kMagic.size()));
  uint32_t version = 0;
  uint8_t kind = 0;
  if (!in.Get(version) || !in.Get(kind)) return Fail(problem, "it is truncated");
  if (version != kMeshWireVersion) {
    return Fail(problem, fmt::format("it is of version {}, not {} (a reader from another build?)",
                                     version, kMeshWireVersion));
  }
  if (kind == kErrorReply) {
    uint8_t over_limit = 0;
    uint64_t length = 0;
    if (!in.Get(over_limit) || !in.Get(length) || over_limit > 1) {
      return Fail(problem, "its error header is truncated or invalid");
    }
    if (length != in.left()) return Fail(problem, "its error message length does not match");
    MeshOrError result{nullptr, std::string(in.Take(length)), over_limit == 1};
    if (result.error.empty()) return Fail(problem, "its error message is empty");
    return result;
  }
  if (kind != kMeshReply) return Fail(problem, fmt::format("it is of unknown kind {}", kind));
  uint8_t declared_up = 0, turned = 0;
  uint64_t vertices = 0, triangles = 0;
  if (!in.Get(declared_up) || !in.Get(turned) || !in.Get(vertices) || !in.Get(triangles)) {
    return Fail(problem, "its mesh header is truncated");
  }
  if (declared_up > static_cast<uint8_t>(UpAxis::kZ) || turned > 1) {
    return Fail(problem, fmt::format("its up axis ({}, turned {}) is invalid", declared_up, turned));
  }
  // indices are int32: more vertices than that cannot be named
  if (vertices > uint64_t{INT32_MAX} || !in.Holds(vertices, 3 * sizeof(double))) {
    return Fail(problem, fmt::format("it claims {} vertices, more than it holds", vertices));
  }
  const uint64_t vertex_bytes = vertices * 3 * sizeof(double);
  const uint64_t after_vertices = in.left() - vertex_bytes;
  // the triangles, then at least the colour count
  const uint64_t triangle_bytes = triangles * 3 * sizeof(int32_t);
  if (after_vertices < sizeof(uint64_t) ||
      triangles > (after_vertices - sizeof(uint64_t)) / (3 * sizeof(int32_t))) {
    return Fail(problem, fmt::format("its size does not match {} vertices and {} triangles",
                                     vertices, triangles));
  }
  // a point cloud (no triangles) is a mesh too: its reader takes the hull
  if (triangles == 0 && vertices == 0) return Fail(problem, "its mesh has no vertices");
  auto mesh = std::make_shared<TriangleMesh>();
  mesh->declared_up = static_cast<UpAxis>(declared_up);
  mesh->turned_to_z_up = turned == 1;
  // the arrays as EncodeMeshReply wrote them: packed coefficients
  // (a point cloud's triangle array is empty: its data() may be null, which
  // memcpy may not be given even for zero bytes)
  mesh->vertices.resize(vertices);
  if (vertex_bytes > 0) {
    std::memcpy(static_cast<void*>(mesh->vertices.data()), in.Take(vertex_bytes).data(),
                vertex_bytes);
  }
  mesh->triangles.resize(triangles);
  if (triangle_bytes > 0) {
    std::memcpy(static_cast<void*>(mesh->triangles.data()), in.Take(triangle_bytes).data(),
                triangle_bytes);
  }
  if (auto bad = DecodeColors(in, triangles, mesh->colors)) return Fail(problem, *bad);
  for (size_t t = 0; t < triangles; ++t) {
    for (int k = 0; k < 3; ++k) {
      const int32_t index = mesh->triangles[t][k];
      if (index < 0 || static_cast<uint64_t>(index) >= vertices) {
        return Fail(problem, fmt::format("its triangle {} names vertex {} of {}", t, index,
                                         vertices));
      }
    }
  }
  return MeshOrError{std::move(mesh), {}};
}

}  // namespace mdlc::mesh
