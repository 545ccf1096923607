// SHA-256 against the FIPS 180-4 examples (one block, two blocks) and the empty message.
#include "exact/sha256.h"

#include <gtest/gtest.h>

#include <random>
#include <string>

namespace contactcert::exact {

TEST(Sha256, EmptyMessage) {
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
}

TEST(Sha256, OneBlock) {
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
}

TEST(Sha256, TwoBlocks) {
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

TEST(Sha256, ManyBlocks) {
  for (Sha256Engine e : {Sha256Engine::kFastest, Sha256Engine::kPortable})
    EXPECT_EQ(sha256_hex(std::string(1000000, 'a'), e),
              "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

// The CPU's SHA instructions (where present) and the portable rounds give the same digest at every length around
// the block and padding boundaries.
TEST(Sha256, InstructionsAgreeWithPortableRounds) {
  std::mt19937 rng(7);
  std::string data;
  for (int n = 0; n <= 300; ++n) {
    EXPECT_EQ(sha256_hex(data, Sha256Engine::kFastest), sha256_hex(data, Sha256Engine::kPortable)) << n;
    data += static_cast<char>(rng());
  }
}

}  // namespace contactcert::exact
