#include "load_context.hpp"

namespace ambf_like::detail {

void LoadContext::warn(SourceRef where, std::string message) {
  warnings_.push_back({std::move(where), std::move(message)});
}

void LoadContext::defer(SourceRef where, std::string message) {
  errors_.push_back({std::move(where), std::move(message)});
}

void LoadContext::throwIfDeferred() const {
  if (!errors_.empty()) throw LoadError(errors_);
}

}  // namespace ambf_like::detail
