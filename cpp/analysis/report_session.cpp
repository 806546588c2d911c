#include "analysis/report_session.hpp"

#include <cstdio>

#include "surface/same_surface.hpp"

namespace pdesurf {
namespace {

// A declared join's own fields as text: a part keyed on it is measured again when any changes.
std::string meetsIdentity(const Meets& m) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "|%d%d%d%d%d%d%d%d%d|%a|%a|%a|%a|", m.end, m.alongU, m.atT1, m.curve, m.replacesT1, m.namedT, m.reversed,
                m.sourceEdge, m.eased, m.v0, m.v1, m.targetFrom, m.targetTo);
  return m.patch + buf + m.by;
}

}  // namespace

void ReportSession::begin(const Scene& scene, const std::vector<SolvedPatch>& solved, int crossingGrid) {
  scene_ = &scene;
  solved_ = &solved;
  crossingGrid_ = crossingGrid;
  next_ = measured_ = kept_ = 0;
  crossing_.reset();
  report_ = SceneReport{};
  bodies_.clear();
  // Versions: a patch keeps its version while its surface is exactly the same.
  current_.assign(solved.size(), 0);
  std::map<std::string, std::pair<SeparableSurface, uint64_t>> seen;
  for (size_t i = 0; i < solved.size(); ++i) {
    const std::string& name = solved[i].patch->name;
    auto it = surfaces_.find(name);
    const bool same = it != surfaces_.end() && sameSurface(it->second.first, solved[i].surface);
    // A surface is copied only when it changed (an edit changes few; the copy is its terms).
    current_[i] = same ? it->second.second : ++versions_;
    if (same) seen[name] = std::move(it->second);
    else seen[name] = {solved[i].surface, current_[i]};
  }
  surfaces_.swap(seen);  // patches gone from the scene are forgotten
  report_.sceneSize = sceneSizeOf(solved);
  parts_.clear();
  for (size_t i = 0; i < solved.size(); ++i)
    for (size_t k = 0; k < solved[i].patch->meets.size(); ++k) parts_.push_back({Kind::Join, i, k});
  for (size_t i = 0; i < solved.size(); ++i) parts_.push_back({Kind::Seam, i, 0});
  for (size_t i = 0; i < solved.size(); ++i)
    if (solved[i].patch->isFill()) parts_.push_back({Kind::Centre, i, 0});
  // The bodies in pieces: each face's integrals (its own surface's), then the topology.
  faces_.assign(solved.size(), FaceMeasure{});
  for (size_t i = 0; i < solved.size(); ++i) parts_.push_back({Kind::Face, i, 0});
  parts_.push_back({Kind::Bodies, 0, 0});
  if (crossingGrid > 0) parts_.push_back({Kind::Crossings, 0, 0});
  // Forget what no part of this scene can use.
  std::map<std::string, Kept> keep;
  for (const Part& p : parts_) {
    auto it = kept_parts_.find(nameOf(p));
    if (it != kept_parts_.end()) keep.insert(*it);
  }
  kept_parts_.swap(keep);
}

std::string ReportSession::nameOf(const Part& p) const {
  const std::vector<SolvedPatch>& s = *solved_;
  switch (p.kind) {
    case Kind::Join: return "join " + s[p.patch].patch->name + "#" + std::to_string(p.meets);
    case Kind::Seam: return "seam " + s[p.patch].patch->name;
    case Kind::Centre: return "centre " + s[p.patch].patch->name;
    case Kind::Face: return "face " + s[p.patch].patch->name;
    case Kind::Bodies: return "bodies";
    case Kind::Crossings: return "crossings";
  }
  return "";
}

ReportSession::Key ReportSession::keyOf(const Part& p) const {
  const std::vector<SolvedPatch>& s = *solved_;
  Key k;
  auto versionOf = [&](const std::string& name) {
    for (size_t i = 0; i < s.size(); ++i)
      if (s[i].patch->name == name) return current_[i];
    return uint64_t{0};
  };
  switch (p.kind) {
    case Kind::Join: {
      const Meets& m = s[p.patch].patch->meets[p.meets];
      k.versions = {current_[p.patch], versionOf(m.patch)};
      k.identity = s[p.patch].patch->name + "|" + meetsIdentity(m);
      break;
    }
    case Kind::Seam:
    case Kind::Centre:
    case Kind::Face:
      k.versions = {current_[p.patch]};
      k.identity = s[p.patch].patch->name;
      break;
    case Kind::Bodies:
    case Kind::Crossings:
      // Everything: every surface, every declared join (the topology follows them; the scene's
      // size, their scale, is a function of the surfaces).
      k.versions = current_;
      for (const SolvedPatch& sp : s) {
        k.identity += sp.patch->name + ";";
        for (const Meets& m : sp.patch->meets) k.identity += meetsIdentity(m) + ";";
      }
      if (p.kind == Kind::Crossings) k.identity += "grid " + std::to_string(crossingGrid_);
      break;
  }
  return k;
}

bool ReportSession::step() {
  while (next_ < parts_.size()) {
    const Part& p = parts_[next_];
    const std::string name = nameOf(p);
    const Key key = keyOf(p);
    auto it = kept_parts_.find(name);
    if (it != kept_parts_.end() && it->second.key == key) {
      place(p, it->second);
      ++next_, ++kept_;
      continue;  // taken as it was: no work, on to the next
    }
    Kept k;
    k.key = key;
    const std::vector<SolvedPatch>& s = *solved_;
    if (p.kind == Kind::Crossings) {  // in steps of its own: a whole search held the worker ~200 ms
      if (!crossing_) crossing_ = std::make_unique<CrossingSearch>(s, report_.sceneSize, crossingGrid_);
      if (!crossing_->step()) return false;
      k.crossings = crossing_->found();
      crossing_.reset();
    }
    switch (p.kind) {
      case Kind::Join: k.join = certifyJoin(*scene_, s, p.patch, p.meets); break;
      case Kind::Seam:
        if (auto r = certifySeam(s[p.patch])) k.join = *r, k.seam = true;
        break;
      case Kind::Centre: k.centre = measureFillCentre(s[p.patch].patch->name, s[p.patch].surface); break;
      case Kind::Face: k.face = faceMeasure(s[p.patch].surface); break;
      case Kind::Bodies: k.bodies = measureBodies(s, report_.sceneSize, &faces_); break;
      case Kind::Crossings: break;  // above
    }
    kept_parts_[name] = k;
    place(p, k);
    ++next_, ++measured_;
    break;  // one measured part a step
  }
  if (next_ < parts_.size()) return false;
  SceneReport& r = report_;
  r.ok = r.crossings.empty();
  for (const JoinResult& j : r.joins) r.ok = r.ok && j.ok;
  for (const JoinResult& j : r.seams) r.ok = r.ok && j.ok;
  for (const FillCentre& c : r.centres) r.ok = r.ok && c.ok;
  return true;
}

// In checkScene's order: parts are made and stepped in it.
void ReportSession::place(const Part& p, const Kept& k) {
  switch (p.kind) {
    case Kind::Join: report_.joins.push_back(k.join); break;
    case Kind::Seam:
      if (k.seam) report_.seams.push_back(k.join);
      break;
    case Kind::Centre: report_.centres.push_back(k.centre); break;
    case Kind::Face: faces_[p.patch] = k.face; break;
    case Kind::Bodies: bodies_ = k.bodies; break;
    case Kind::Crossings: report_.crossings = k.crossings; break;
  }
}

}  // namespace pdesurf
