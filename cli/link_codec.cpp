#include "link_codec.hpp"

#include <zlib.h>

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
  inflateEnd(&z);
  return out;
}

std::string encodeLink(const std::string& stateJson) {
  return "s=" + std::to_string(kLinkVersion) + "." + base64urlEncode(deflateRaw(stateJson));
}

std::string decodeLink(const std::string& link) {
  std::string s = link;
  const size_t hash = s.find('#');
  if (hash != std::string::npos) s = s.substr(hash + 1);
  if (s.rfind("s=", 0) != 0) throw std::runtime_error("not a pdesurf link: expected '#s=<version>.<data>'");
  s = s.substr(2);
  const size_t dot = s.find('.');
  if (dot == std::string::npos) throw std::runtime_error("not a pdesurf link: no version");
  const std::string version = s.substr(0, dot);
  // One decoder per link version, kept forever. Version 1: deflate-raw JSON.
  if (version == "1") return inflateRaw(base64urlDecode(s.substr(dot + 1)), kMaxInflatedBytes);
  throw std::runtime_error("unknown link version '" + version.substr(0, 16) + "' (this build reads version 1)");
}

}  // namespace pdesurf::cli
