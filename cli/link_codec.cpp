#include "link_codec.hpp"

#include <zlib.h>

#include <algorithm>
#include <stdexcept>

namespace pdesurf::cli {

namespace {
const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";

int sextet(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '-') return 62;
  if (c == '_') return 63;
  return -1;
}
// Some tools percent-encode what they copy; base64url itself never contains '%'. Strict: a
// '%' not followed by two hex digits is damage (as for the page's decodeURIComponent).
std::string percentDecode(const std::string& s) {
  const auto hex = [](char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
  };
  std::string out;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] != '%') {
      out += s[i];
      continue;
    }
    const int hi = i + 2 < s.size() ? hex(s[i + 1]) : -1, lo = i + 2 < s.size() ? hex(s[i + 2]) : -1;
    if (hi < 0 || lo < 0) throw std::runtime_error("the link is damaged: bad percent-encoding");
    out += static_cast<char>(hi * 16 + lo);
    i += 2;
  }
  return out;
}

}  // namespace

std::string base64urlEncode(const std::string& bytes) {
  std::string out;
  size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned n = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                       static_cast<unsigned char>(bytes[i + 2]);
    out += kAlphabet[n >> 18], out += kAlphabet[(n >> 12) & 63], out += kAlphabet[(n >> 6) & 63], out += kAlphabet[n & 63];
  }
  const size_t rest = bytes.size() - i;
  if (rest == 1) {
    const unsigned n = static_cast<unsigned char>(bytes[i]) << 16;
    out += kAlphabet[n >> 18], out += kAlphabet[(n >> 12) & 63];
  } else if (rest == 2) {
    const unsigned n = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8);
    out += kAlphabet[n >> 18], out += kAlphabet[(n >> 12) & 63], out += kAlphabet[(n >> 6) & 63];
  }
  return out;
}

std::string base64urlDecode(const std::string& text) {
  if (text.size() % 4 == 1) throw std::runtime_error("bad base64: truncated");
  std::string out;
  unsigned buffer = 0;
  int bits = 0;
  for (char c : text) {
    const int v = sextet(c);
    if (v < 0) throw std::runtime_error(std::string("bad base64: unexpected character '") + c + "'");
    buffer = (buffer << 6) | static_cast<unsigned>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out += static_cast<char>((buffer >> bits) & 0xFF);
    }
  }
  return out;
}

std::string deflateRaw(const std::string& bytes) {
  z_stream z{};
  if (deflateInit2(&z, 9, Z_DEFLATED, -15, 9, Z_DEFAULT_STRATEGY) != Z_OK) throw std::runtime_error("deflate: cannot start");
  std::string out(deflateBound(&z, bytes.size()), '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  z.avail_in = static_cast<uInt>(bytes.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  const int rc = deflate(&z, Z_FINISH);
  const size_t produced = z.total_out;
  deflateEnd(&z);
  if (rc != Z_STREAM_END) throw std::runtime_error("deflate failed");
  out.resize(produced);
  return out;
}

std::string inflateRaw(const std::string& bytes, size_t maxBytes) {
  z_stream z{};
  if (inflateInit2(&z, -15) != Z_OK) throw std::runtime_error("inflate: cannot start");
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  z.avail_in = static_cast<uInt>(bytes.size());
  std::string out;
  char chunk[16384];
  int rc = Z_OK;
  // Chunk by chunk, so an inflate bomb stops at the cap instead of allocating its full size.
  while (rc != Z_STREAM_END) {
    z.next_out = reinterpret_cast<Bytef*>(chunk);
    z.avail_out = sizeof chunk;
    rc = inflate(&z, Z_NO_FLUSH);
    if (rc != Z_OK && rc != Z_STREAM_END) {
      inflateEnd(&z);
      throw std::runtime_error(rc == Z_BUF_ERROR ? "the link is truncated (the compressed stream ends early)" : "the compressed stream is broken");
    }
    out.append(chunk, sizeof chunk - z.avail_out);
    if (out.size() > maxBytes) {
      inflateEnd(&z);
      throw std::runtime_error("the link inflates to more than " + std::to_string(maxBytes) + " bytes");
    }
  }
  const uInt trailing = z.avail_in;
  inflateEnd(&z);
  // A second stream or junk after the first would make the link mean two things.
  if (trailing != 0) throw std::runtime_error("the link is damaged: " + std::to_string(trailing) + " bytes after the end of its compressed data");
  return out;
}

std::string encodeLink(const std::string& stateJson) {
  return "s=" + std::to_string(kLinkVersion) + "." + base64urlEncode(deflateRaw(stateJson));
}

std::string decodeLink(const std::string& link) {
  if (link.size() > limits::kLinkChars) throw std::runtime_error("the link is too long (" + std::to_string(link.size()) + " characters)");
  std::string s = link;
  const size_t hash = s.find('#');
  if (hash != std::string::npos) s = s.substr(hash + 1);
  std::string compact;  // chats and mail wrap long links: whitespace is never part of one
  for (char c : s)
    if (c != ' ' && c != '\t' && c != '\n' && c != '\r' && c != '\f' && c != '\v') compact += c;
  std::string field;
  bool found = false;
  for (size_t start = 0; start <= compact.size() && !found;) {
    const size_t end = std::min(compact.find('&', start), compact.size());
    if (compact.compare(start, 2, "s=") == 0) field = compact.substr(start + 2, end - start - 2), found = true;
    start = end + 1;
  }
  if (!found) throw std::runtime_error("not a pdesurf link: it holds no page state (\"s=...\")");
  if (field.find('%') != std::string::npos) field = percentDecode(field);
  const size_t dot = field.find('.');
  if (dot == std::string::npos) throw std::runtime_error("the link is damaged: expected \"s=<version>.<data>\"");
  const std::string version = field.substr(0, dot);
  // One decoder per link version, kept forever. Version 1: deflate-raw JSON.
  if (version != "1") throw std::runtime_error("unknown link version '" + version.substr(0, 16) + "' (this build reads version 1)");
  if (dot + 1 == field.size()) throw std::runtime_error("the link is damaged: it carries no data");
  return inflateRaw(base64urlDecode(field.substr(dot + 1)), kMaxInflatedBytes);
}

}  // namespace pdesurf::cli
