// Where a B-spline fit refines next (bspline_fit.cpp): the knot spans in each direction with
// the certificate's cells inside them, and the plan that says how many pieces each span is cut
// into and how many cells each keeps. The plan predicts what the next round needs from the
// errors' orders (a span's least-squares residual falls as h^(p+1), a cell's slack as h²), so
// a fit reaches its tolerance in a few rounds instead of one halving per round.
#pragma once
#include <vector>

#include "cad/fit_certificate.hpp"

namespace pdesurf {

// One direction's spans: breaks[0] < … < breaks[n]; span s holds cuts[s] certificate cells;
// crease[k] says breaks[k] is a crease (a knot of full multiplicity).
struct SpanSet {
  std::vector<double> breaks;
  std::vector<int> cuts;
  std::vector<bool> crease;
  int count() const { return int(breaks.size()) - 1; }
};

// Uniform spans on [a, b] with `cells` cells each; creases put in (a break within a tenth of a
// span of a crease gives way to it; a single span between creases is halved).
SpanSet initialSpans(double a, double b, int spans, int cells, const std::vector<double>& creases);

// The certificate grid of a span set: each span cut into its cells; spanOf names each cell's span.
void certificateLine(const SpanSet& s, std::vector<double>* t, std::vector<int>* spanOf);

// Per span: into how many equal pieces it is cut (1: kept) and its cells' new count.
struct RefinePlan {
  using Pieces = std::vector<int>;
  Pieces piecesU, piecesV;
  std::vector<int> cutsU, cutsV;
  bool splitsSpans() const;
};

struct RefineInput {
  const SpanSet* u;
  const SpanSet* v;
  const CertificateGrid* grid;
  const Certificate* cert;
  const std::vector<double>* uResidual;  // each span's largest 1D least-squares residual
  const std::vector<double>* vResidual;
  double tolerance;
  double normalToleranceDeg;
  int degree;
  bool periodicV;
};

RefinePlan planRefinement(const RefineInput& in);

// The spans after the plan: each cut into its pieces (each piece keeps the plan's cells).
void applyPlan(SpanSet& s, const std::vector<int>& pieces, const std::vector<int>& cuts);

}  // namespace pdesurf
