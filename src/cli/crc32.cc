// Copyright contactlaws authors.
//
// The fold. A message's CRC register after its bytes is (M(x) x^32) mod P
// (the register's own start folded into the message's first 32 bits), P
// the CRC-32 polynomial, bits reflected: a byte's lowest bit is its highest
// coefficient, and a 128-bit block X, its 16 bytes read little-endian, is
// H x^64 + L with H its first 8 bytes. A block followed by F more bits N is
// congruent (mod P, all the register needs) to
//   H (x^(64 + F) mod P) + L (x^F mod P) + N,
// a 128-bit block again: two carry-less products of 64 by 32 bits. Reflected
// operands give their product times x, so the constants are x^(63 + F) and
// x^(F - 1) mod P. Four blocks are folded side by side over 64 bytes
// (F = 512), then into one (F = 384, 256, 128), then 16 bytes at a time; the
// last block's remainder (X x^32 mod P) and the bytes after it are zlib's.

#include "cli/crc32.h"

#include <zlib.h>

#include <array>
#include <cstring>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define CONTACTLAWS_CRC32_FOLD 1
#endif

namespace contactlaws::cli {
namespace {

uint32_t Zlib(uint32_t crc, const unsigned char* data, size_t size) {
  return static_cast<uint32_t>(crc32_z(crc, data, static_cast<z_size_t>(size)));
}

#ifdef CONTACTLAWS_CRC32_FOLD

// x^n mod P, reflected into the 64-bit operand a carry-less product takes:
// the coefficient of x^d at bit 63 - d.
uint64_t PowerOfX(int n) {
  constexpr uint32_t kPolynomial = 0x04c11db7;  // P less its x^32, x^31 at bit 31
  uint32_t r = 1;                                // x^0, normal order
  for (int i = 0; i < n; ++i) r = (r << 1) ^ ((r & 0x80000000u) ? kPolynomial : 0);
  uint64_t reflected = 0;
  for (int d = 0; d < 32; ++d) {
    if (r & (1u << d)) reflected |= uint64_t{1} << (63 - d);
  }
  return reflected;
}

struct Constants {
  // {x^(63 + F), x^(F - 1)} mod P for a fold over F bits
  std::array<uint64_t, 2> f512, f384, f256, f128;
};

const Constants& FoldConstants() {
  static const Constants constants = [] {
    auto fold = [](int f) { return std::array<uint64_t, 2>{PowerOfX(63 + f), PowerOfX(f - 1)}; };
    return Constants{fold(512), fold(384), fold(256), fold(128)};
  }();
  return constants;
}

__attribute__((target("pclmul,sse2"))) inline __m128i Fold(__m128i x, __m128i k) {
  return _mm_xor_si128(_mm_clmulepi64_si128(x, k, 0x00), _mm_clmulepi64_si128(x, k, 0x11));
}

__attribute__((target("pclmul,sse2"))) __m128i Load(const unsigned char* p) {
  return _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
}

__attribute__((target("pclmul,sse2"))) __m128i Constant(const std::array<uint64_t, 2>& k) {
  return _mm_set_epi64x(static_cast<long long>(k[1]), static_cast<long long>(k[0]));
}

// size >= 64
__attribute__((target("pclmul,sse2"))) uint32_t Folded(uint32_t crc, const unsigned char* data,
                                                       size_t size) {
  const Constants& c = FoldConstants();
  const __m128i k512 = Constant(c.f512);
  // the register (zlib's crc inverted) into the first 32 bits
  __m128i x0 = _mm_xor_si128(Load(data), _mm_cvtsi32_si128(static_cast<int>(~crc)));
  __m128i x1 = Load(data + 16);
  __m128i x2 = Load(data + 32);
  __m128i x3 = Load(data + 48);
  data += 64;
  size -= 64;
  for (; size >= 64; data += 64, size -= 64) {
    x0 = _mm_xor_si128(Fold(x0, k512), Load(data));
    x1 = _mm_xor_si128(Fold(x1, k512), Load(data + 16));
    x2 = _mm_xor_si128(Fold(x2, k512), Load(data + 32));
    x3 = _mm_xor_si128(Fold(x3, k512), Load(data + 48));
  }
  __m128i x = _mm_xor_si128(_mm_xor_si128(Fold(x0, Constant(c.f384)), Fold(x1, Constant(c.f256))),
                            _mm_xor_si128(Fold(x2, Constant(c.f128)), x3));
  const __m128i k128 = Constant(c.f128);
  for (; size >= 16; data += 16, size -= 16) x = _mm_xor_si128(Fold(x, k128), Load(data));
  // X x^32 mod P is the register after X's 16 bytes from a register of 0:
  // zlib's crc32 from ~0 (which it inverts to 0), inverted back
  unsigned char block[16];
  _mm_storeu_si128(reinterpret_cast<__m128i*>(block), x);
  const uint32_t register_after = ~Zlib(0xffffffffu, block, sizeof block);
  return Zlib(~register_after, data, size);
}

#endif  // CONTACTLAWS_CRC32_FOLD

}  // namespace

bool Crc32Folds() {
#ifdef CONTACTLAWS_CRC32_FOLD
  static const bool folds = __builtin_cpu_supports("pclmul") && __builtin_cpu_supports("sse2");
  return folds;
#else
  return false;
#endif
}

uint32_t Crc32(uint32_t crc, const void* data, size_t size) {
  const auto* bytes = static_cast<const unsigned char*>(data);
#ifdef CONTACTLAWS_CRC32_FOLD
  if (size >= 64 && Crc32Folds()) return Folded(crc, bytes, size);
#endif
  return Zlib(crc, bytes, size);
}

}  // namespace contactlaws::cli
