#pragma once
// The benchmark's results: one row per measured quantity, printed as a Markdown table and
// written as JSON.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace bench {

/// The spread of repeated measurements.
struct Spread {
  double median = 0.0, min = 0.0, max = 0.0;
  static Spread of(std::vector<double> samples);
};

/// One measured quantity, with the target it is held to (if any).
struct Row {
  std::string section;  ///< "loop frequency", "controller", ...
  std::string item;     ///< what was measured
  Spread value;
  std::string unit;
  std::string target;       ///< e.g. ">= 5000"; empty: none
  std::optional<bool> met;  ///< whether the median meets the target
  std::string note;         ///< how it was measured, or why it was skipped
  bool skipped = false;
};

/// Every row of a run, and where it ran.
class Report {
 public:
  void add(Row row) { rows_.push_back(std::move(row)); }
  /// A row that could not be measured here, and why.
  void skip(std::string section, std::string item, std::string why);
  const std::vector<Row>& rows() const { return rows_; }

  /// "| section | item | value | target | met | note |" table (ranges when repeated).
  std::string markdown() const;
  nlohmann::json json(const nlohmann::json& machine) const;

 private:
  std::vector<Row> rows_;
};

/// A row whose target is a lower bound: met when the median reaches `bound`.
Row atLeast(std::string section, std::string item, Spread value, std::string unit, double bound,
            std::string note);
/// A row whose target is an upper bound: met when the median stays under `bound`.
Row atMost(std::string section, std::string item, Spread value, std::string unit, double bound,
           std::string note);
/// A row without a target.
Row measured(std::string section, std::string item, Spread value, std::string unit,
             std::string note);

/// The p-th percentile (0..100) of `samples` (nearest rank); 0 for none.
double percentile(std::vector<double> samples, double p);

}  // namespace bench
