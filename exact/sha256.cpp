#include "exact/sha256.h"

#include <array>
#include <cstdint>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <cpuid.h>
#include <immintrin.h>
#endif

namespace contactcert::exact {
namespace {

using Word = std::uint32_t;

// FIPS 180-4 section 4.2.2: the first 32 bits of the fractional parts of the cube roots of the first 64 primes.
constexpr std::array<Word, 64> kRound = {
    0x428a2f98, 0x71374491, 0xb5c0fbcf, 0xe9b5dba5, 0x3956c25b, 0x59f111f1, 0x923f82a4, 0xab1c5ed5,
    0xd807aa98, 0x12835b01, 0x243185be, 0x550c7dc3, 0x72be5d74, 0x80deb1fe, 0x9bdc06a7, 0xc19bf174,
    0xe49b69c1, 0xefbe4786, 0x0fc19dc6, 0x240ca1cc, 0x2de92c6f, 0x4a7484aa, 0x5cb0a9dc, 0x76f988da,
    0x983e5152, 0xa831c66d, 0xb00327c8, 0xbf597fc7, 0xc6e00bf3, 0xd5a79147, 0x06ca6351, 0x14292967,
    0x27b70a85, 0x2e1b2138, 0x4d2c6dfc, 0x53380d13, 0x650a7354, 0x766a0abb, 0x81c2c92e, 0x92722c85,
    0xa2bfe8a1, 0xa81a664b, 0xc24b8b70, 0xc76c51a3, 0xd192e819, 0xd6990624, 0xf40e3585, 0x106aa070,
    0x19a4c116, 0x1e376c08, 0x2748774c, 0x34b0bcb5, 0x391c0cb3, 0x4ed8aa4a, 0x5b9cca4f, 0x682e6ff3,
    0x748f82ee, 0x78a5636f, 0x84c87814, 0x8cc70208, 0x90befffa, 0xa4506ceb, 0xbef9a3f7, 0xc67178f2};

constexpr Word rotr(Word x, int n) { return (x >> n) | (x << (32 - n)); }

/// Section 6.2.2: one 64-byte block into the hash state h.
void compress(std::array<Word, 8>& h, const unsigned char* block) {
  std::array<Word, 64> w{};
  for (int t = 0; t < 16; ++t)
    w[t] =
        Word(block[4 * t]) << 24 | Word(block[4 * t + 1]) << 16 | Word(block[4 * t + 2]) << 8 | Word(block[4 * t + 3]);
  for (int t = 16; t < 64; ++t) {
    const Word s0 = rotr(w[t - 15], 7) ^ rotr(w[t - 15], 18) ^ (w[t - 15] >> 3);
    const Word s1 = rotr(w[t - 2], 17) ^ rotr(w[t - 2], 19) ^ (w[t - 2] >> 10);
    w[t] = w[t - 16] + s0 + w[t - 7] + s1;
  }
  Word a = h[0], b = h[1], c = h[2], d = h[3], e = h[4], f = h[5], g = h[6], k = h[7];
  for (int t = 0; t < 64; ++t) {
    const Word t1 = k + (rotr(e, 6) ^ rotr(e, 11) ^ rotr(e, 25)) + ((e & f) ^ (~e & g)) + kRound[t] + w[t];
    const Word t2 = (rotr(a, 2) ^ rotr(a, 13) ^ rotr(a, 22)) + ((a & b) ^ (a & c) ^ (b & c));
    k = g, g = f, f = e, e = d + t1, d = c, c = b, b = a, a = t1 + t2;
  }
  h[0] += a, h[1] += b, h[2] += c, h[3] += d, h[4] += e, h[5] += f, h[6] += g, h[7] += k;
}

void compress_portable(std::array<Word, 8>& h, const unsigned char* blocks, std::size_t n) {
  for (std::size_t b = 0; b < n; ++b) compress(h, blocks + 64 * b);
}

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
/// The CPU has the SHA extensions (CPUID.7.0:EBX bit 29) and the SSSE3 and SSE4.1 shuffles used around them.
bool cpu_has_sha() {
  unsigned a = 0, b = 0, c = 0, d = 0;
  if (!__get_cpuid_count(7, 0, &a, &b, &c, &d) || ((b >> 29) & 1) == 0) return false;
  return __get_cpuid(1, &a, &b, &c, &d) && ((c >> 9) & 1) != 0 && ((c >> 19) & 1) != 0;
}

/// Section 6.2.2 on the SHA extensions: sha256rnds2 does two rounds on the state held as (A, B, E, F) and (C, D, G,
/// H); sha256msg1 adds sigma0 and sha256msg2 sigma1 of the message schedule, four words at a time.
__attribute__((target("sha,ssse3,sse4.1"))) void compress_sha_ni(std::array<Word, 8>& h, const unsigned char* blocks,
                                                                 std::size_t n) {
  const __m128i big_endian = _mm_set_epi64x(0x0c0d0e0f08090a0bLL, 0x0405060700010203LL);
  const __m128i cdab = _mm_shuffle_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(&h[0])), 0xB1);
  const __m128i efgh = _mm_shuffle_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(&h[4])), 0x1B);
  __m128i abef = _mm_alignr_epi8(cdab, efgh, 8);
  __m128i cdgh = _mm_blend_epi16(efgh, cdab, 0xF0);
  for (std::size_t b = 0; b < n; ++b) {
    const unsigned char* block = blocks + 64 * b;
    const __m128i abef_in = abef, cdgh_in = cdgh;
    __m128i w[4];  // words 4g .. 4g + 3 of the schedule, in a ring of four groups
    for (int g = 0; g < 16; ++g) {
      __m128i& x = w[g % 4];
      if (g < 4) {
        x = _mm_shuffle_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(block + 16 * g)), big_endian);
      } else {  // W_t = sigma1(W_t-2) + W_t-7 + sigma0(W_t-15) + W_t-16
        const __m128i& w1 = w[(g + 3) % 4];
        const __m128i w7 = _mm_alignr_epi8(w1, w[(g + 2) % 4], 4);
        x = _mm_sha256msg2_epu32(_mm_add_epi32(_mm_sha256msg1_epu32(x, w[(g + 1) % 4]), w7), w1);
      }
      const __m128i wk = _mm_add_epi32(x, _mm_loadu_si128(reinterpret_cast<const __m128i*>(&kRound[4 * g])));
      cdgh = _mm_sha256rnds2_epu32(cdgh, abef, wk);                           // now the new (A, B, E, F)
      abef = _mm_sha256rnds2_epu32(abef, cdgh, _mm_shuffle_epi32(wk, 0x0E));  // and again: roles restored
    }
    abef = _mm_add_epi32(abef, abef_in);
    cdgh = _mm_add_epi32(cdgh, cdgh_in);
  }
  const __m128i feba = _mm_shuffle_epi32(abef, 0x1B);
  const __m128i dchg = _mm_shuffle_epi32(cdgh, 0xB1);
  _mm_storeu_si128(reinterpret_cast<__m128i*>(&h[0]), _mm_blend_epi16(feba, dchg, 0xF0));
  _mm_storeu_si128(reinterpret_cast<__m128i*>(&h[4]), _mm_alignr_epi8(dchg, feba, 8));
}
#endif

using Compress = void (*)(std::array<Word, 8>&, const unsigned char*, std::size_t);

Compress compress_for(Sha256Engine engine) {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  static const bool sha_ni = cpu_has_sha();
  if (engine == Sha256Engine::kFastest && sha_ni) return compress_sha_ni;
#endif
  (void)engine;
  return compress_portable;
}

}  // namespace

std::string sha256_hex(std::string_view data, Sha256Engine engine) {
  const Compress compress_blocks = compress_for(engine);
  // Section 5.3.3: the initial hash value (square roots of the first 8 primes).
  std::array<Word, 8> h = {0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a,
                           0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19};
  const std::size_t i = data.size() / 64 * 64;
  compress_blocks(h, reinterpret_cast<const unsigned char*>(data.data()), data.size() / 64);
  // Section 5.1.1: the message, a 1 bit, zeros, and its length in bits as 64 bits big-endian.
  std::array<unsigned char, 128> tail{};
  const std::size_t rest = (data.size() - i) % 64;  // < 64 by the loop above; % says so to the compiler
  for (std::size_t k = 0; k < rest; ++k) tail[k] = static_cast<unsigned char>(data[i + k]);
  tail[rest] = 0x80;
  const std::size_t blocks = rest + 9 <= 64 ? 1 : 2;
  const std::uint64_t bits = static_cast<std::uint64_t>(data.size()) * 8;
  for (int k = 0; k < 8; ++k) tail[blocks * 64 - 1 - k] = static_cast<unsigned char>(bits >> (8 * k));
  compress_blocks(h, tail.data(), blocks);
  static const char* const kHex = "0123456789abcdef";
  std::string out;
  for (Word x : h)
    for (int s = 28; s >= 0; s -= 4) out += kHex[(x >> s) & 0xf];
  return out;
}

}  // namespace contactcert::exact
