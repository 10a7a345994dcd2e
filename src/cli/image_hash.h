#pragma once
/// \file
/// \brief The fingerprint of an image that `raycache render --hash` prints and the web edition's
/// page writes into #image-hash: the same hex digits mean the same pixels, byte for byte.
#include <cstdint>
#include <string>
#include <vector>

namespace rc::cli {

/// SHA-256 of `bytes`, as 64 lower-case hex digits (OpenSSL's libcrypto computes it).
std::string sha256Hex(const std::vector<std::uint8_t>& bytes);

}  // namespace rc::cli
