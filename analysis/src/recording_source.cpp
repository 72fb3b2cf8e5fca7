#include "analysis/recording_source.hpp"

#include "common/yaml_view.hpp"

namespace analysis {

bool RecordingSource::claims(const std::filesystem::path& file,
                             const recording::RsVariant& variant) const {
  if (ambf_rows && variant.from_ambf) return true;
  const std::string file_name = file.filename().string();
  for (const auto& pattern : file_patterns) {
    if (file_name.find(pattern) != std::string::npos) return true;
  }
  for (const auto& pattern : file_regexes) {
    if (std::regex_search(file_name, pattern)) return true;
  }
  return false;
}

std::vector<RecordingSource> readRecordingSources(const std::filesystem::path& file) {
  const auto root = common::YamlView::parseFile(file);
  std::vector<common::LoadIssue> warnings;
  const common::KeyCheck strict{true, warnings};
  root.checkKeys({"platforms"}, strict);
  std::vector<RecordingSource> profiles;
  for (const auto& entry : root["platforms"].elements()) {
    entry.checkKeys(
        {"name", "label", "role", "files", "file regex", "ambf rows", "position offsets"}, strict);
    RecordingSource p;
    p.name = entry["name"].asString();
    p.label = entry.find("label") ? entry["label"].asString() : p.name;
    const auto role = entry["role"];
    if (role.asKeyword() == "physical") {
      p.role = Role::Physical;
    } else if (role.asKeyword() != "simulation") {
      role.fail("role must be 'physical' or 'simulation'");
    }
    if (auto files = entry.find("files")) {
      for (const auto& f : files->elements()) p.file_patterns.push_back(f.asString());
    }
    if (auto regexes = entry.find("file regex")) {
      for (const auto& r : regexes->elements()) {
        try {
          p.file_regexes.emplace_back(r.asString());
        } catch (const std::regex_error& e) {
          r.fail(std::string("not a regular expression: ") + e.what());
        }
      }
    }
    p.ambf_rows = entry.getBool("ambf rows", false);
    if (auto offsets = entry.find("position offsets")) {
      for (const auto& key : offsets->keys()) {
        int column = -1;
        for (int c = 0; c < kJointColumns; ++c) {
          if (key == "jpos" + std::to_string(c)) column = c;
        }
        if (column < 0) (*offsets)[key].fail("not a joint column (jpos0..jpos15)");
        p.position_offset[static_cast<std::size_t>(column)] = (*offsets)[key].asDouble();
      }
    }
    for (const auto& other : profiles) {
      if (other.name == p.name) entry["name"].fail("platform '" + p.name + "' is defined twice");
    }
    profiles.push_back(std::move(p));
  }
  if (profiles.empty()) root["platforms"].fail("no platforms");
  return profiles;
}

std::filesystem::path defaultRecordingSourcesFile() {
  return RAVEN_ANALYSIS_PROFILES;
}

const RecordingSource* sourceOf(const std::vector<RecordingSource>& profiles,
                                const std::filesystem::path& file,
                                const recording::RsVariant& variant) {
  for (const auto& p : profiles) {
    if (p.claims(file, variant)) return &p;
  }
  return nullptr;
}

}  // namespace analysis
