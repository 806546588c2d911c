// Shareable links, natively (docs/scene-format-v2.md): "s=<version>.<base64url(deflate-raw(JSON))>".
// The page does the same with CompressionStream; tests check the two agree both ways.
#pragma once
#include <string>

namespace pdesurf::cli {

constexpr int kLinkVersion = 1;
constexpr size_t kMaxInflatedBytes = 1 << 20;

// JSON text -> "s=1.…" (no '#').
std::string encodeLink(const std::string& stateJson);
// A URL, "#s=…" or "s=…" -> the JSON text. Throws std::runtime_error naming what is wrong:
// unknown version, bad base64, broken deflate stream, more than 1 MiB once inflated.
std::string decodeLink(const std::string& link);

std::string base64urlEncode(const std::string& bytes);
std::string base64urlDecode(const std::string& text);  // throws on bad input
std::string deflateRaw(const std::string& bytes);
std::string inflateRaw(const std::string& bytes, size_t maxBytes);  // throws past maxBytes

}  // namespace pdesurf::cli
