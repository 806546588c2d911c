// fitScene on several threads, for the CLI (the core stays single-threaded: the page's wasm
// module has none). Expressions are hash-consed per thread and carry lazily built caches
// (compiled programs, derivatives), so threads must not share one: each extra thread parses
// and solves the scene itself (milliseconds) and fits patches of its own copy; only the
// B-splines, plain numbers, come back. The patches go out one at a time to whichever thread is
// free, the likely longest first; the faces are the same, bit for bit, on any number.
#pragma once
#include <string>
#include <vector>

#include "cad/scene_fit.hpp"

namespace pdesurf::cli {

// jobs: threads in all (this one included), at least 1. Throws the error of the first patch in
// the scene's order that fails, as fitScene would (patches after it are not started).
std::vector<PatchFit> fitSceneOnThreads(const std::string& sceneText, const std::vector<SolvedPatch>& solved,
                                        const FitOptions& fit, int jobs);

// The default of --jobs: the machine's hardware threads, at most 8.
int defaultJobs();

}  // namespace pdesurf::cli
