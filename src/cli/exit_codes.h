#pragma once
// lenslab's exit statuses (docs/cli.md): 0 done, 1 the work failed (a lens or scene that cannot be
// loaded, a file that cannot be written, an analysis that cannot run), 2 a usage error.

namespace lenslab::cli {

inline constexpr int kFailure = 1;
inline constexpr int kUsageError = 2;

}  // namespace lenslab::cli
