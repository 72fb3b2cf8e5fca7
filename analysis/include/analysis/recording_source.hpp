#pragma once
// Recording sources: which recordings belong to a platform and how its recorded joint columns
// map onto the physical Raven-II's convention (analysis/profiles/platforms.yaml). Not a
// raven::PlatformProfile, which is a platform's kinematics (R_P, R_S).

#include <array>
#include <filesystem>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "recording/recording_io.hpp"

namespace analysis {

/// jpos0..15 (or jvel0..15) of one rs row: left arm 0-7, right arm 8-15, 3 and 11 unused.
constexpr int kJointColumns = 16;
using JointRow = std::array<double, kJointColumns>;

/// The paper's notation: comparisons within the physical robot are T_PP, within a simulator T_SS,
/// across the two T_PS.
enum class Role { Physical, Simulation };

/// One platform's recordings and conventions.
struct RecordingSource {
  std::string name;   ///< short key used in reports ("ambf")
  std::string label;  ///< for figures ("AMBF")
  Role role = Role::Simulation;
  std::vector<std::string> file_patterns;  ///< a file whose name contains one belongs here
  /// A file whose name matches one (ECMAScript, anywhere in the name) belongs here too.
  std::vector<std::regex> file_regexes;
  bool ambf_rows = false;      ///< also claims files the reader identifies as AMBF's
  JointRow position_offset{};  ///< added to recorded jpos (rad, m)

  /// Does this recording belong to the platform?
  bool claims(const std::filesystem::path& file, const recording::RsVariant& variant) const;
};

/// Reads a recording sources file. Throws common::LoadError naming the file, line and key.
std::vector<RecordingSource> readRecordingSources(const std::filesystem::path& file);
/// analysis/profiles/platforms.yaml of this source tree.
std::filesystem::path defaultRecordingSourcesFile();

/// The first source claiming the file, if any.
const RecordingSource* sourceOf(const std::vector<RecordingSource>& profiles,
                                const std::filesystem::path& file,
                                const recording::RsVariant& variant);

}  // namespace analysis
