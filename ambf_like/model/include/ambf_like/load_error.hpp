#pragma once
// The loader's error types (shared with the rest of the project through `common`).

#include "common/load_error.hpp"

namespace ambf_like {

using common::LoadError;
using common::LoadIssue;
using common::SourceRef;

}  // namespace ambf_like
