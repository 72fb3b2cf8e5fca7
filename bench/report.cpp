#include "report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace bench {

namespace {

std::string number(double v) {
  const double a = std::abs(v);
  if (a >= 1000.0) return fmt::format("{:.0f}", v);
  if (a >= 100.0) return fmt::format("{:.1f}", v);
  if (a >= 1.0) return fmt::format("{:.2f}", v);
  return fmt::format("{:.3g}", v);
}

std::string show(const Spread& s) {
  if (s.min == s.max) return number(s.median);
  return fmt::format("{} ({}-{})", number(s.median), number(s.min), number(s.max));
}

Row bounded(std::string section, std::string item, Spread value, std::string unit,
            std::string target, bool met, std::string note) {
  return {std::move(section), std::move(item), value, std::move(unit), std::move(target), met,
          std::move(note)};
}

}  // namespace

Spread Spread::of(std::vector<double> samples) {
  if (samples.empty()) return {};
  std::sort(samples.begin(), samples.end());
  const std::size_t n = samples.size();
  const double median = n % 2 == 1 ? samples[n / 2] : 0.5 * (samples[n / 2 - 1] + samples[n / 2]);
  return {median, samples.front(), samples.back()};
}

double percentile(std::vector<double> samples, double p) {
  if (samples.empty()) return 0.0;
  std::sort(samples.begin(), samples.end());
  const double rank = std::ceil(p / 100.0 * static_cast<double>(samples.size()));
  const auto index = static_cast<std::size_t>(std::clamp(rank, 1.0, double(samples.size())));
  return samples[index - 1];
}

Row atLeast(std::string section, std::string item, Spread value, std::string unit, double bound,
            std::string note) {
  return bounded(std::move(section), std::move(item), value, unit,
                 ">= " + number(bound) + " " + unit, value.median >= bound, std::move(note));
}

Row atMost(std::string section, std::string item, Spread value, std::string unit, double bound,
           std::string note) {
  return bounded(std::move(section), std::move(item), value, unit,
                 "< " + number(bound) + " " + unit, value.median < bound, std::move(note));
}

Row measured(std::string section, std::string item, Spread value, std::string unit,
             std::string note) {
  return {std::move(section), std::move(item), value, std::move(unit), "",
          std::nullopt,       std::move(note)};
}

void Report::skip(std::string section, std::string item, std::string why) {
  Row row{std::move(section), std::move(item), {}, "", "", std::nullopt, std::move(why)};
  row.skipped = true;
  rows_.push_back(std::move(row));
}

std::string Report::markdown() const {
  std::string out = "| section | measurement | value | target | note |\n|---|---|---|---|---|\n";
  for (const Row& r : rows_) {
    const std::string value = r.skipped ? "skipped" : show(r.value) + " " + r.unit;
    std::string target = r.target;
    if (r.met) target += *r.met ? " (met)" : " (**not met**)";
    out += fmt::format("| {} | {} | {} | {} | {} |\n", r.section, r.item, value, target, r.note);
  }
  return out;
}

nlohmann::json Report::json(const nlohmann::json& machine) const {
  nlohmann::json rows = nlohmann::json::array();
  for (const Row& r : rows_) {
    nlohmann::json j{{"section", r.section}, {"item", r.item}, {"note", r.note}};
    if (r.skipped) {
      j["skipped"] = true;
    } else {
      j["median"] = r.value.median;
      j["min"] = r.value.min;
      j["max"] = r.value.max;
      j["unit"] = r.unit;
    }
    if (!r.target.empty()) j["target"] = r.target;
    if (r.met) j["met"] = *r.met;
    rows.push_back(j);
  }
  return {{"machine", machine}, {"rows", rows}};
}

}  // namespace bench
