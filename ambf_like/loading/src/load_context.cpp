#include "load_context.hpp"

namespace ambf_like::detail {

void LoadContext::warn(SourceRef where, std::string message) {
  warnings_.push_back({std::move(where), std::move(message)});
}

void LoadContext::tolerate(SourceRef where, std::string message) {
  if (options_.strict) {
    defer(std::move(where), std::move(message));
  } else {
    warn(std::move(where), std::move(message));
  }
}

void LoadContext::acceptedNotSimulated(SourceRef where, const std::string& key) {
  if (noted_keys_.insert(key).second) {
    warn(std::move(where), "'" + key + "' accepted, not simulated (noted once per load)");
  }
}

void LoadContext::defer(SourceRef where, std::string message) {
  errors_.push_back({std::move(where), std::move(message)});
}

void LoadContext::throwIfDeferred() const {
  if (!errors_.empty()) throw LoadError(errors_);
}

}  // namespace ambf_like::detail
