// Shareable links, natively (docs/scene-format-v2.md): "s=<version>.<base64url(deflate-raw(JSON))>".
// The page does the same with CompressionStream; tests check the two agree both ways.
#pragma once
#include <string>

#include "common/limits.hpp"

namespace pdesurf::cli {

constexpr int kLinkVersion = 1;
constexpr size_t kMaxInflatedBytes = limits::kInflatedBytes;

// JSON text -> "s=1.…" (no '#').
std::string encodeLink(const std::string& stateJson);
// A URL, "#s=…" or "s=…" -> the JSON text. The same rules as the page's codec
// (web/link/link-codec.js; docs/limits.md): whitespace is dropped (mail wraps links), the
// state is the "s=" field among '&'-separated ones, the version is exactly "1" after
// percent-decoding, nothing after the end of the deflate stream. Throws std::runtime_error
// naming what is wrong: too long, unknown version, bad base64, broken or trailing deflate
// data, more than 1 MiB once inflated.
std::string decodeLink(const std::string& link);

std::string base64urlEncode(const std::string& bytes);
std::string base64urlDecode(const std::string& text);  // throws on bad input
std::string deflateRaw(const std::string& bytes);
std::string inflateRaw(const std::string& bytes, size_t maxBytes);  // throws past maxBytes

}  // namespace pdesurf::cli
