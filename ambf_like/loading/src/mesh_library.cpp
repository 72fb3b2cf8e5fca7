#include <assimp/DefaultIOSystem.h>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cctype>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <unordered_map>

#include "ambf_like/mesh.hpp"
#include "collada_instances.hpp"
#include "common/farthest.hpp"
#include "common/file_problem.hpp"
#include "common/lower_case.hpp"
#include "common/xml_nesting.hpp"
#include "vtk_tet_mesh.hpp"

namespace ambf_like {

namespace {

/// Exact-position key for welding vertices that files store once per triangle (e.g. STL).
struct PositionKey {
  double x, y, z;
  bool operator==(const PositionKey& other) const {
    return x == other.x && y == other.y && z == other.z;
  }
};

struct PositionHash {
  std::size_t operator()(const PositionKey& key) const {
    std::size_t seed = 0;
    for (double v : {key.x, key.y, key.z}) {
      std::uint64_t bits;
      std::memcpy(&bits, &v, sizeof bits);
      seed ^= std::hash<std::uint64_t>{}(bits) + 0x9e3779b97f4a7c15ULL + (seed << 6) + (seed >> 2);
    }
    return seed;
  }
};

/// Keeps only vertices that a tetrahedron or a triangle uses, so vertex i is soft-body node i
/// (an unused point would be a massless, that is fixed, node).
void dropUnreferencedVertices(Mesh& mesh) {
  // In the file's order (a `fixed nodes` index is a point of the file), the unused left out.
  std::vector<char> used(mesh.vertices.size(), 0);
  for (const auto& tetrahedron : mesh.tetrahedra)
    for (int index : tetrahedron) used[static_cast<std::size_t>(index)] = 1;
  for (const auto& triangle : mesh.triangles)
    for (int index : triangle) used[static_cast<std::size_t>(index)] = 1;
  std::vector<int> remap(mesh.vertices.size(), -1);
  std::vector<Vec3> kept;
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    if (!used[i]) continue;
    remap[i] = static_cast<int>(kept.size());
    kept.push_back(mesh.vertices[i]);
  }
  auto renumber = [&](int& index) { index = remap[static_cast<std::size_t>(index)]; };
  for (auto& tetrahedron : mesh.tetrahedra)
    std::for_each(tetrahedron.begin(), tetrahedron.end(), renumber);
  for (auto& triangle : mesh.triangles) std::for_each(triangle.begin(), triangle.end(), renumber);
  mesh.vertices = std::move(kept);
}

/// Refuses a vertex that is not finite or lies beyond common::kFarthestCoordinate.
void checkVertices(const Mesh& mesh, const SourceRef& referenced_from) {
  constexpr double kFarthest = common::kFarthestCoordinate;
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vec3& v = mesh.vertices[i];
    if (!v.allFinite() || v.cwiseAbs().maxCoeff() > kFarthest) {
      std::ostringstream text;
      text << "mesh " << mesh.file.string() << ": vertex " << i << " at (" << v.x() << ", " << v.y()
           << ", " << v.z() << ") is not finite or lies beyond +-" << kFarthest;
      throw LoadError(referenced_from, text.str());
    }
  }
}

/// Refuses a tetrahedron whose volume is below a billionth of its longest edge cubed: a sliver
/// with its points (nearly) in one plane, whose shape matrix has no useful inverse and whose
/// volume's sign rounding decides.
void checkTetrahedra(const Mesh& mesh, const SourceRef& referenced_from) {
  constexpr double kFlatness = 1e-9;
  for (std::size_t c = 0; c < mesh.tetrahedra.size(); ++c) {
    const auto& t = mesh.tetrahedra[c];
    auto corner = [&](int k) -> const Vec3& {
      return mesh.vertices[static_cast<std::size_t>(t[k])];
    };
    double longest = 0.0;
    for (int i = 0; i < 4; ++i) {
      for (int j = i + 1; j < 4; ++j) longest = std::max(longest, (corner(i) - corner(j)).norm());
    }
    if (!(mesh.volume(t) > kFlatness * longest * longest * longest)) {
      throw LoadError(referenced_from, "mesh " + mesh.file.string() + ": cell " +
                                           std::to_string(c) +
                                           " is flat (no volume to speak of for its size)");
    }
  }
}

/// The line of the first COLLADA index list (<p>, <v>, <vcount>) holding anything but
/// non-negative integers and white space, if any: assimp 5.2 reads "1@2" in one as an index of
/// billions and allocates gigabytes for it (found by fuzz_mesh).
std::optional<std::size_t> malformedColladaIndexList(const std::string& text) {
  for (const char* tag : {"<p>", "<v>", "<vcount>"}) {
    const std::string close = std::string("</") + (tag + 1);
    for (auto open = text.find(tag); open != std::string::npos; open = text.find(tag, open + 1)) {
      const auto begin = open + std::strlen(tag);
      const auto end = text.find(close, begin);
      if (end == std::string::npos) break;
      const auto bad = text.find_first_not_of("0123456789 \t\r\n", begin);
      if (bad < end)
        return 1 + static_cast<std::size_t>(
                       std::count(text.begin(), text.begin() + static_cast<long>(bad), '\n'));
    }
  }
  return std::nullopt;
}

/// The line of the first COLLADA <float_array> or <int_array> whose `count` is missing or is not
/// the number of values it holds (assimp 5.2 reads an accessor's values past an array declared
/// shorter).
std::optional<std::size_t> miscountedColladaArray(const std::string& text) {
  for (const char* tag : {"<float_array", "<int_array"}) {
    for (auto open = text.find(tag); open != std::string::npos; open = text.find(tag, open + 1)) {
      const auto body = text.find('>', open);
      const auto end = text.find('<', body);
      if (body == std::string::npos || end == std::string::npos) break;
      const std::string head = text.substr(open, body - open);
      // The attribute named `count` exactly: one named "xcount" leaves assimp none, and it
      // then reads the accessor's values from an empty array (found by fuzz_mesh).
      auto count_at = head.find("count=\"");
      while (count_at != std::string::npos &&
             !std::isspace(static_cast<unsigned char>(head[count_at - 1]))) {
        count_at = head.find("count=\"", count_at + 1);
      }
      const std::string declared =
          count_at == std::string::npos
              ? std::string()
              : head.substr(count_at + 7, head.find('"', count_at + 7) - (count_at + 7));
      std::size_t values = 0;
      std::istringstream tokens(text.substr(body + 1, end - body - 1));
      for (std::string token; tokens >> token;) ++values;
      if (declared != std::to_string(values)) {
        return 1 + static_cast<std::size_t>(
                       std::count(text.begin(), text.begin() + static_cast<long>(open), '\n'));
      }
    }
  }
  return std::nullopt;
}

/// assimp's XML formats (COLLADA and others, whatever the file is called) recurse once per
/// nested node until the stack ends: a file that is XML is measured first, and its COLLADA
/// index lists, arrays and node instances checked.
template <typename Fail>
void refuseDeepXml(const std::filesystem::path& file, Fail fail) {
  std::ifstream in(file, std::ios::binary);
  std::string start(64, '\0');
  in.read(start.data(), static_cast<std::streamsize>(start.size()));
  start.resize(static_cast<std::size_t>(in.gcount()));
  const auto first = start.find_first_not_of(" \t\r\n\xEF\xBB\xBF");
  if (first == std::string::npos || start[first] != '<') return;
  in.clear();
  in.seekg(0);
  std::stringstream text;
  text << in.rdbuf();
  if (const auto line = common::xmlNestedBeyond(text.str(), common::kMostXmlNesting)) {
    throw fail("line " + std::to_string(*line) + ": elements nested deeper than " +
               std::to_string(common::kMostXmlNesting) + " levels; no mesh nests so deep");
  }
  if (const auto line = malformedColladaIndexList(text.str())) {
    throw fail("line " + std::to_string(*line) +
               ": an index list (<p>, <v> or <vcount>) holds something other than whole numbers");
  }
  if (const auto line = miscountedColladaArray(text.str())) {
    throw fail("line " + std::to_string(*line) +
               ": an array's count is not the number of values it holds");
  }
  if (const auto problem = detail::colladaInstanceProblem(text.str())) {
    throw fail("line " + std::to_string(problem->line) + ": " + problem->what);
  }
}

/// The files assimp opens besides the mesh (an OBJ's material library, ...), each only if it is a
/// regular file: opening a named pipe blocks until something writes to it, and a device may never
/// end.
class RegularFilesOnly : public Assimp::DefaultIOSystem {
 public:
  bool Exists(const char* file) const override { return common::isReadableFile(file); }
  Assimp::IOStream* Open(const char* file, const char* mode) override {
    return common::isReadableFile(file) ? DefaultIOSystem::Open(file, mode) : nullptr;
  }
};

/// The file's extension in lower case (AMBF's own files say .STL and .3DS).
std::string extensionOf(const std::filesystem::path& file) {
  return common::lowerCase(file.extension().string());
}

/// The surface formats AMBF reads (CHAI3D's STL, OBJ and 3DS) and COLLADA. assimp knows some
/// forty more, each a parser of its own that hostile bytes could reach; none is let through.
bool surfaceFormat(const std::filesystem::path& file) {
  const std::string extension = extensionOf(file);
  return extension == ".stl" || extension == ".obj" || extension == ".3ds" || extension == ".dae";
}

Mesh readMesh(const std::filesystem::path& file, const SourceRef& referenced_from) {
  auto fail = [&](const std::string& message) -> LoadError {
    return LoadError(referenced_from, "mesh " + file.string() + ": " + message);
  };
  if (const auto problem = common::fileProblem(file); !problem.empty()) throw fail(problem);
  if (!surfaceFormat(file)) {
    throw fail(
        "not a mesh format read here: a surface mesh is .stl, .obj, .3ds or .dae, a "
        "volume mesh .vtk");
  }
  refuseDeepXml(file, fail);

  Assimp::Importer importer;
  importer.SetIOHandler(new RegularFilesOnly);  // the importer owns it
  // Keep a Z-up COLLADA file's coordinates as written (assimp would turn it Y-up).
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  const unsigned flags = aiProcess_Triangulate | aiProcess_DropNormals |
                         aiProcess_JoinIdenticalVertices | aiProcess_PreTransformVertices;
  const aiScene* scene = importer.ReadFile(file.string(), flags);
  if (scene == nullptr || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) != 0) {
    throw fail(std::string("cannot read: ") + importer.GetErrorString());
  }

  Mesh mesh;
  mesh.file = file;
  std::unordered_map<PositionKey, int, PositionHash> index_of;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* part = scene->mMeshes[m];
    std::vector<int> remap(part->mNumVertices);
    for (unsigned v = 0; v < part->mNumVertices; ++v) {
      const auto& p = part->mVertices[v];
      const PositionKey key{p.x, p.y, p.z};
      auto [it, inserted] = index_of.emplace(key, static_cast<int>(mesh.vertices.size()));
      if (inserted) mesh.vertices.emplace_back(p.x, p.y, p.z);
      remap[v] = it->second;
    }
    for (unsigned f = 0; f < part->mNumFaces; ++f) {
      const aiFace& face = part->mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines carry no surface
      const std::array<int, 3> tri{remap[face.mIndices[0]], remap[face.mIndices[1]],
                                   remap[face.mIndices[2]]};
      if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) continue;  // degenerate
      mesh.triangles.push_back(tri);
    }
  }
  if (mesh.triangles.empty()) throw fail("the file holds no triangles");
  dropUnreferencedVertices(mesh);
  checkVertices(mesh, referenced_from);
  return mesh;
}

}  // namespace

Vec3 Mesh::centroid() const {
  Vec3 sum = Vec3::Zero();
  for (const auto& v : vertices) sum += v;
  return vertices.empty() ? sum : Vec3(sum / static_cast<double>(vertices.size()));
}

double Mesh::volume(const std::array<int, 4>& tetrahedron) const {
  auto corner = [&](int k) -> const Vec3& {
    return vertices[static_cast<std::size_t>(tetrahedron[static_cast<std::size_t>(k)])];
  };
  return (corner(1) - corner(0)).cross(corner(2) - corner(0)).dot(corner(3) - corner(0)) / 6.0;
}

std::shared_ptr<const Mesh> MeshLibrary::load(const std::filesystem::path& file,
                                              const SourceRef& referenced_from) {
  if (auto it = cache_.find(file); it != cache_.end()) return it->second;
  std::shared_ptr<const Mesh> mesh;
  if (extensionOf(file) == ".vtk") {
    try {
      Mesh volume = detail::readVtkTetMesh(file);
      dropUnreferencedVertices(volume);
      mesh = std::make_shared<const Mesh>(std::move(volume));
    } catch (const LoadError& error) {
      auto issues = error.issues();
      issues.push_back({referenced_from, "the tetrahedral mesh above is referenced here"});
      throw LoadError(std::move(issues));
    }
    checkVertices(*mesh, referenced_from);
    checkTetrahedra(*mesh, referenced_from);
  } else {
    mesh = std::make_shared<const Mesh>(readMesh(file, referenced_from));
  }
  cache_.emplace(file, mesh);
  return mesh;
}

}  // namespace ambf_like
