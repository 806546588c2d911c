#include "methods/method.hpp"

#include <cstdlib>

#include "common/errors.hpp"
#include "methods/approximate.hpp"
#include "pde/closed_form.hpp"

namespace pdesurf {

namespace {

// Fourier modes for a tube with a corner on its seam: the examples' modal:64 (the corner's
// remainder is then carried within ~1/130 of the edge that has it).
constexpr int kSeamCornerModes = 64;

// A count from 1 to `most` (Fourier and pseudo-spectral expansions: 1000, their solvers' own
// bound, refused here rather than after the scene is read and solved).
int parseCount(const std::string& text, const std::string& whole, long most = 4096) {
  char* end = nullptr;
  const bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
  const long v = digits && text.size() <= 9 ? std::strtol(text.c_str(), &end, 10) : 0;
  if (!digits || v < 1 || v > most)
    throw Error(ErrorCode::InvalidField, "method '" + whole + "': expected a whole number of terms from 1 to " + std::to_string(most) + ", got '" + text + "'");
  return static_cast<int>(v);
}

}  // namespace

Method parseMethod(const std::string& text) {
  const size_t colon = text.find(':');
  const std::string name = text.substr(0, colon);
  const std::string arg = colon == std::string::npos ? "" : text.substr(colon + 1);
  Method m;
  auto needs = [&](bool wantArg) {
    if (wantArg && arg.empty()) throw Error(ErrorCode::InvalidField, "method '" + name + "' needs a number of terms, e.g. '" + name + ":20'");
    if (!wantArg && colon != std::string::npos) throw Error(ErrorCode::InvalidField, "method '" + name + "' takes no options");
  };
  if (name == "auto") needs(false), m.kind = MethodKind::Auto;
  else if (name == "closed") needs(false), m.kind = MethodKind::Closed;
  else if (name == "reference") needs(false), m.kind = MethodKind::Reference;
  else if (name == "modal") needs(true), m.kind = MethodKind::Modal, m.terms = parseCount(arg, text);
  else if (name == "fourier") needs(true), m.kind = MethodKind::Fourier, m.terms = parseCount(arg, text, 1000);
  else if (name == "pseudo-spectral") needs(true), m.kind = MethodKind::PseudoSpectral, m.terms = parseCount(arg, text, 1000);
  else if (name == "pseudo-navier") {
    m.kind = MethodKind::PseudoNavier;
    if (colon != std::string::npos) {  // M,N,L
      const size_t a = arg.find(','), b = arg.find(',', a == std::string::npos ? a : a + 1);
      if (a == std::string::npos || b == std::string::npos)
        throw Error(ErrorCode::InvalidField, "method '" + text + "': expected pseudo-navier:M,N,L");
      m.navierM = parseCount(arg.substr(0, a), text);
      m.navierN = parseCount(arg.substr(a + 1, b - a - 1), text);
      m.navierPoints = parseCount(arg.substr(b + 1), text);
    }
  } else {
    throw Error(ErrorCode::InvalidField, "unknown method '" + text + "' (auto, closed, pseudo-navier, modal:N, fourier:N, pseudo-spectral:N, reference)");
  }
  return m;
}

std::string methodName(const Method& m) {
  switch (m.kind) {
    case MethodKind::Auto: return "auto";
    case MethodKind::Closed: return "closed";
    case MethodKind::Reference: return "reference";
    case MethodKind::Modal: return "modal:" + std::to_string(m.terms);
    case MethodKind::Fourier: return "fourier:" + std::to_string(m.terms);
    case MethodKind::PseudoSpectral: return "pseudo-spectral:" + std::to_string(m.terms);
    case MethodKind::PseudoNavier:
      if (m.navierM == 3 && m.navierN == 3 && m.navierPoints == 49) return "pseudo-navier";
      return "pseudo-navier:" + std::to_string(m.navierM) + "," + std::to_string(m.navierN) + "," + std::to_string(m.navierPoints);
  }
  return "?";
}

std::vector<std::string> applicableMethods(const PdeProblem& p) {
  bool forces = false;
  for (const auto& c : p.component) forces = forces || !c.force.empty();
  std::vector<std::string> out{"auto"};
  PdeProblem restored;
  if (restoreFamilies(p, &restored)) out.push_back("closed");
  out.push_back("pseudo-navier");
  for (const char* m : {"modal:4", "modal:16", "modal:64"}) out.push_back(m);
  if (!forces)
    for (const char* m : {"fourier:20", "fourier:100", "pseudo-spectral:2", "pseudo-spectral:5"}) out.push_back(m);
  out.push_back("reference");
  return out;
}

MethodSolution solveWithMethod(const PdeProblem& p, const Method& m, BasisCache* cache) {
  MethodSolution out;
  out.used = m;
  switch (m.kind) {
    case MethodKind::Auto: {
      // A tube whose data have a corner on the seam and whose families would not close term
      // by term: closed by the modal method's loop (methods/approximate.hpp).
      if (!familyTermsClose(p) && hasSeamCorner(p)) {
        out.used = Method{MethodKind::Modal, kSeamCornerModes};
        out.surface = solveModal(p, kSeamCornerModes, cache);
        return out;
      }
      if (!hasGeneralTerms(p)) {  // the common case: no copy of the problem
        out.surface = solveClosedForm(p, cache);
        out.used.kind = MethodKind::Closed;
        return out;
      }
      // The reference falls back to the closed form itself when every general term has one.
      out = solveReference(p, 1e-9, cache);
      if (out.used.kind == MethodKind::Reference) out.used = Method{MethodKind::Modal, out.referenceTerms};
      return out;
    }
    case MethodKind::Closed: {
      if (!hasGeneralTerms(p)) {
        out.surface = solveClosedForm(p, cache);
        return out;
      }
      PdeProblem restored;
      restoreFamilies(p, &restored);  // what stays general makes the closed form refuse, by name
      out.surface = solveClosedForm(restored, cache);
      return out;
    }
    case MethodKind::Reference: return solveReference(p, 1e-12, cache);
    case MethodKind::Modal: out.surface = solveModal(p, m.terms, cache); return out;
    case MethodKind::Fourier: out.surface = solveFourier(p, m.terms); return out;
    case MethodKind::PseudoSpectral: out.surface = solvePseudoSpectral(p, m.terms); return out;
    case MethodKind::PseudoNavier: out.surface = solvePseudoNavier(p, m.navierM, m.navierN, m.navierPoints); return out;
  }
  return out;
}

}  // namespace pdesurf
