#pragma once
// How strict a load is: set by the caller of the loader, read by every file reader.

namespace ambf_like {

/// How strict a load is.
struct LoadOptions {
  /// Off (the default, AMBF's acceptance): what AMBF's own loader tolerates is a warning naming
  /// file, line and key, and the load goes on: unknown keys (with a did-you-mean), missing mesh
  /// and environment files (the body keeps its mass, without that geometry), a body without
  /// `mass` (static, as AMBF leaves it), a dynamic body whose inertia has nothing to come from
  /// (a stated fallback). On: each of these is an error, for users who want their files checked.
  /// Malformed YAML, wrong types, NaNs and impossible values are errors either way.
  bool strict = false;
};

}  // namespace ambf_like
