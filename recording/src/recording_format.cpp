#include "recording/recording_format.hpp"

#include <charconv>
#include <cmath>

namespace recording {

namespace {

/// The rs columns in order: a stem with a count is numbered stem0..stem<count-1>; a count of 0
/// is one column under the stem itself.
struct ColumnRun {
  const char* stem;
  int count;
};
constexpr ColumnRun kRsColumns[] = {
    {"time", 0},     {"jpos", 16},     {"runlevel", 0}, {"sublevel", 0}, {"last_seq", 0},
    {"type", 2},     {"pos", 6},       {"ori", 18},     {"ori_d", 18},   {"pos_d", 6},
    {"encVals", 16}, {"dac_vals", 16}, {"Tau", 16},     {"mpos", 16},    {"mvel", 16},
    {"jvel", 16},    {"mpos_d", 16},   {"jpos_d", 16},  {"grasp_d", 2},  {"encoffsets", 16},
    {"jac_vel", 12}, {"jac_f", 12},
};

template <typename T, std::size_t N>
void append(std::vector<double>& row, const std::array<T, N>& values, double scale = 1.0) {
  for (const T& v : values) row.push_back(static_cast<double>(v) * scale);
}

}  // namespace

const std::vector<std::string>& rsColumnNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const auto& run : kRsColumns) {
      if (run.count == 0) n.emplace_back(run.stem);
      for (int i = 0; i < run.count; ++i) n.push_back(run.stem + std::to_string(i));
    }
    return n;
  }();
  return names;
}

std::vector<double> rsRow(const bridge::RavenStateSnapshot& s, double t0) {
  constexpr double kRadians = M_PI / 180.0;
  std::vector<double> row;
  row.reserve(240);
  row.push_back(s.time - t0);
  append(row, s.jpos, kRadians);
  row.insert(row.end(), {static_cast<double>(s.runlevel), static_cast<double>(s.sublevel),
                         static_cast<double>(s.last_seq)});
  append(row, s.type);
  append(row, s.pos);
  append(row, s.ori);
  append(row, s.ori_d);
  append(row, s.pos_d);
  append(row, s.enc_vals);
  append(row, s.dac_val);
  append(row, s.tau);
  append(row, s.mpos);
  append(row, s.mvel);
  append(row, s.jvel, kRadians);
  append(row, s.mpos_d);
  append(row, s.jpos_d);
  append(row, s.grasp_d);
  append(row, s.encoffsets);
  append(row, s.jac_vel);
  append(row, s.jac_f);
  return row;
}

std::string formatRsValue(double value, bool round_to_micro) {
  if (std::isnan(value)) return "";
  if (round_to_micro) value = std::round(value * 1e6) / 1e6;
  if (value == 0.0) value = 0.0;  // no "-0.0"
  char buffer[64];
  const auto end = std::to_chars(buffer, buffer + sizeof(buffer), value).ptr;
  std::string text(buffer, end);
  // Python prints integral floats with ".0" and switches to exponents at 1e16 / below 1e-4.
  if (text.find_first_of(".eEn") == std::string::npos) text += ".0";
  return text;
}

}  // namespace recording
