// Whether two solved surfaces are the same surface, exactly: the same ranges, terms and
// pointwise parts (expressions are interned, so the same expression is the same node while
// either is alive). What a cache of anything measured on a surface keys on.
#pragma once
#include "surface/separable_surface.hpp"

namespace pdesurf {

bool sameFunction(const VFunction& a, const VFunction& b);
bool sameSurface(const SeparableSurface& a, const SeparableSurface& b);

}  // namespace pdesurf
