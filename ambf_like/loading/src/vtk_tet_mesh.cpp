#include "vtk_tet_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "common/file_problem.hpp"

namespace ambf_like::detail {

namespace {

constexpr int kVtkTetra = 10;

/// Whitespace-separated tokens of a text file, each with its 1-based line.
class Tokens {
 public:
  explicit Tokens(const std::filesystem::path& file) : file_(file) {
    std::ifstream in(file);
    if (!in) throw LoadError(SourceRef{file, 0, ""}, "cannot open the tetrahedral mesh");
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
      ++number;
      if (number <= 3) {  // version line, title and format line are read whole
        header_.push_back(line);
        continue;
      }
      std::istringstream words(line);
      std::string word;
      while (words >> word) tokens_.push_back({word, number});
    }
  }

  const std::vector<std::string>& header() const { return header_; }
  bool done() const { return next_ >= tokens_.size(); }
  const std::string& peek() const { return tokens_.at(next_).text; }

  std::string word(const std::string& what) {
    if (done()) fail("the file ends where " + what + " was expected");
    return tokens_[next_++].text;
  }
  void expect(const std::string& keyword) {
    const std::string got = word("'" + keyword + "'");
    if (got != keyword) fail("expected '" + keyword + "', found '" + got + "'", -1);
  }
  double number(const std::string& what) {
    const std::string text = word(what);
    try {
      std::size_t used = 0;
      const double value = std::stod(text, &used);
      if (used == text.size() && std::isfinite(value)) return value;
    } catch (const std::exception&) {
    }
    fail(what + " must be a finite number, not '" + text + "'", -1);
  }
  long integer(const std::string& what, long low, long high) {
    const std::string text = word(what);
    try {
      std::size_t used = 0;
      const long value = std::stol(text, &used);
      if (used == text.size() && value >= low && value <= high) return value;
    } catch (const std::exception&) {
    }
    fail(what + " must be a whole number in [" + std::to_string(low) + ", " + std::to_string(high) +
             "], not '" + text + "'",
         -1);
  }
  /// Throws at the last token read (`back` = -1) or the next one.
  [[noreturn]] void fail(const std::string& message, int back = 0) const {
    const std::size_t at = std::min(next_ + static_cast<std::size_t>(back), tokens_.size() - 1);
    const int line = tokens_.empty() ? 0 : tokens_[at].line;
    throw LoadError(SourceRef{file_, line, ""}, message);
  }

 private:
  struct Token {
    std::string text;
    int line;
  };
  std::filesystem::path file_;
  std::vector<std::string> header_;
  std::vector<Token> tokens_;
  std::size_t next_ = 0;
};

/// The faces that belong to one tetrahedron only, wound outward.
std::vector<std::array<int, 3>> boundaryFaces(const std::vector<std::array<int, 4>>& tets) {
  // Each face of a positive tetrahedron (a, b, c, d), wound so its normal leaves the tetrahedron.
  static constexpr int kFaces[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  std::map<std::array<int, 3>, std::pair<int, std::array<int, 3>>> seen;
  for (const auto& t : tets) {
    for (const auto& f : kFaces) {
      const std::array<int, 3> face{t[f[0]], t[f[1]], t[f[2]]};
      std::array<int, 3> key = face;
      std::sort(key.begin(), key.end());
      auto [it, inserted] = seen.emplace(key, std::make_pair(0, face));
      ++it->second.first;
    }
  }
  std::vector<std::array<int, 3>> out;
  for (const auto& [key, entry] : seen) {
    if (entry.first == 1) out.push_back(entry.second);
  }
  return out;
}

}  // namespace

Mesh readVtkTetMesh(const std::filesystem::path& file) {
  if (const auto problem = common::fileProblem(file); !problem.empty()) {
    throw LoadError(SourceRef{file, 0, ""}, "tetrahedral mesh: " + problem);
  }
  Tokens in(file);
  const auto& header = in.header();
  if (header.size() < 3 || header[0].rfind("# vtk DataFile", 0) != 0) {
    throw LoadError(SourceRef{file, 1, ""}, "not a legacy VTK file (no '# vtk DataFile' line)");
  }
  if (header[2].find("ASCII") == std::string::npos) {
    throw LoadError(SourceRef{file, 3, ""},
                    "only ASCII VTK files are read, not '" + header[2] + "'");
  }
  in.expect("DATASET");
  in.expect("UNSTRUCTURED_GRID");
  in.expect("POINTS");
  constexpr long kMaxCount = 10'000'000;
  const long points = in.integer("the point count", 4, kMaxCount);
  in.word("the point type");
  Mesh mesh;
  mesh.file = file;
  mesh.vertices.reserve(static_cast<std::size_t>(points));
  for (long i = 0; i < points; ++i) {
    const double x = in.number("a point's x"), y = in.number("a point's y"),
                 z = in.number("a point's z");
    mesh.vertices.emplace_back(x, y, z);
  }
  in.expect("CELLS");
  const long cells = in.integer("the cell count", 1, kMaxCount);
  in.integer("the CELLS list size", 0, 5 * kMaxCount);
  std::vector<std::array<int, 4>> tets;
  tets.reserve(static_cast<std::size_t>(cells));
  for (long c = 0; c < cells; ++c) {
    const long corners = in.integer("a cell's point count", 1, 64);
    if (corners != 4)
      in.fail("cell " + std::to_string(c) + " has " + std::to_string(corners) +
                  " points: only tetrahedra (4 points) make a volume mesh",
              -1);
    std::array<int, 4> t{};
    for (int& index : t) index = static_cast<int>(in.integer("a point index", 0, points - 1));
    tets.push_back(t);
    const double volume = mesh.volume(t);
    if (!(std::abs(volume) > 0.0)) in.fail("cell " + std::to_string(c) + " has no volume", -1);
    if (volume < 0.0) std::swap(tets.back()[2], tets.back()[3]);
  }
  in.expect("CELL_TYPES");
  in.integer("the CELL_TYPES count", cells, cells);
  for (long c = 0; c < cells; ++c) {
    if (in.integer("a cell type", 0, 100) != kVtkTetra) {
      in.fail("cell " + std::to_string(c) + " is not a tetrahedron (VTK type 10)", -1);
    }
  }
  // Point or cell data may follow; the geometry is complete.
  mesh.tetrahedra = std::move(tets);
  mesh.triangles = boundaryFaces(mesh.tetrahedra);
  return mesh;
}

}  // namespace ambf_like::detail
