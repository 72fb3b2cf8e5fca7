#include <fmt/format.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "analysis/report.hpp"

namespace analysis {

namespace {

namespace fs = std::filesystem;

bool isPicture(const fs::path& file) {
  const auto ext = file.extension();
  return ext == ".png" || ext == ".mp4" || ext == ".mkv" || ext == ".webm";
}

}  // namespace

std::size_t writePictures(const std::vector<fs::path>& inputs, const fs::path& dir) {
  std::set<fs::path> folders, found;
  for (const fs::path& input : inputs) {
    folders.insert(fs::is_directory(input) ? input : input.parent_path());
  }
  for (const fs::path& folder : folders) {
    if (folder.empty() || !fs::is_directory(folder)) continue;
    for (const auto& entry : fs::directory_iterator(folder)) {
      if (entry.is_regular_file() && isPicture(entry.path())) found.insert(entry.path());
    }
  }
  nlohmann::json list = nlohmann::json::array();
  if (found.empty()) return 0;
  const fs::path pictures = dir / "pictures";
  fs::create_directories(pictures);
  std::set<fs::path> posters;
  for (const fs::path& file : found) {
    if (file.extension() == ".png") continue;
    const fs::path poster = fs::path(file).replace_extension(".png");
    if (found.count(poster)) posters.insert(poster);
  }
  for (const fs::path& file : found) {
    std::error_code failed;
    fs::copy_file(file, pictures / file.filename(), fs::copy_options::overwrite_existing, failed);
    if (failed) {
      throw std::runtime_error(fmt::format("cannot copy {} into {}: {}", file.string(),
                                           pictures.string(), failed.message()));
    }
    if (posters.count(file)) continue;  // shown as its video's poster
    nlohmann::json item{{"file", "pictures/" + file.filename().string()},
                        {"kind", file.extension() == ".png" ? "image" : "video"}};
    const fs::path poster = fs::path(file).replace_extension(".png");
    if (file.extension() != ".png" && posters.count(poster)) {
      item["poster"] = "pictures/" + poster.filename().string();
    }
    list.push_back(item);
  }
  std::ofstream out(dir / "pictures.json");
  out << list.dump(2) << '\n';
  if (!out) throw std::runtime_error("cannot write " + (dir / "pictures.json").string());
  return list.size();
}

}  // namespace analysis
