// The join report of an editor that re-solves on every edit (the page's worker), beside the
// one-off checkScene: a stateful session that measures the report one part at a time (a join,
// a seam, a fill's centre, the bodies, the crossings), so its caller can stop between parts
// when a newer edit makes the report stale, and that keeps every part it measured: a part
// whose inputs are the same as last time (the same surfaces, exactly, the same declared join)
// is taken as it was: a join's tolerances are its own (not the scene's size), so an edit of
// one wing re-measures that wing's joins and nothing else but the bodies and the crossings.
#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "analysis/bodies.hpp"
#include "analysis/crossings.hpp"
#include "analysis/join_certificate.hpp"

namespace pdesurf {

class ReportSession {
 public:
  // Starts the report of `solved` (of `scene`): both must outlive the steps up to the next
  // begin. crossingGrid: the crossings' mesh per patch (0: none), as checkScene's.
  void begin(const Scene& scene, const std::vector<SolvedPatch>& solved, int crossingGrid = 0);
  // Measures the next part not kept from before (the crossings, a step of their search);
  // true when the report is complete (then report() is). Throws what the part's measure throws (a declared join that is not one).
  bool step();
  size_t partsLeft() const { return parts_.size() - next_; }
  size_t partsMeasured() const { return measured_; }  // in this report, not taken from before
  size_t partsKept() const { return kept_; }
  // checkScene's report, with the bodies (measureBodies).
  const SceneReport& report() const { return report_; }
  const std::vector<Body>& bodies() const { return bodies_; }

 private:
  enum class Kind { Join, Seam, Centre, Face, Bodies, Crossings };
  struct Part {
    Kind kind;
    size_t patch = 0, meets = 0;  // Join: solved[patch].meets[meets]; Seam, Centre, Face: solved[patch]
  };
  // What a part read: its surfaces' versions, its declared join, the grid.
  struct Key {
    std::vector<uint64_t> versions;
    std::string identity;  // names, the declared join's fields, the grid
    bool operator==(const Key& o) const { return versions == o.versions && identity == o.identity; }
  };
  struct Kept {
    Key key;
    JoinResult join;
    FillCentre centre;
    FaceMeasure face;  // a patch's area and volume integrals (the bodies sum them)
    std::vector<Body> bodies;
    std::vector<Crossing> crossings;
    bool seam = false;  // a seam part: join holds it, or the patch does not close (seam false)
  };
  Key keyOf(const Part& p) const;
  std::string nameOf(const Part& p) const;
  void place(const Part& p, const Kept& k);

  const Scene* scene_ = nullptr;
  const std::vector<SolvedPatch>* solved_ = nullptr;
  int crossingGrid_ = 0;
  std::vector<Part> parts_;
  size_t next_ = 0, measured_ = 0, kept_ = 0;
  SceneReport report_;
  std::vector<Body> bodies_;
  std::vector<FaceMeasure> faces_;  // per solved patch, from its Face part
  // Per patch name: the surface last seen and its version (bumped when it changes).
  std::map<std::string, std::pair<SeparableSurface, uint64_t>> surfaces_;
  uint64_t versions_ = 0;
  std::vector<uint64_t> current_;  // each solved patch's version in this report
  std::map<std::string, Kept> kept_parts_;  // by part name
  std::unique_ptr<CrossingSearch> crossing_;  // the crossings part under way
};

}  // namespace pdesurf
