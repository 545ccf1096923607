// Augmented contact modes (wrench cone paper, section 2.3 and Table 2; SPEC section 5): one letter
// per fixel from s a u l r n m, and the constraints each letter puts on y = (a_n, a_t, c_n, c_t).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace contactcert::solvers {

/// One contact interaction of Table 2.
enum class Interaction : char {
  kSeparate = 's',         ///< a_n >= 0 (> 0 when touching: strictly separating, docs/papers.md), c = 0
  kApproach = 'a',         ///< a_n < 0, c = 0; needs a gap
  kUnconstrained = 'u',    ///< c = 0; needs a gap
  kSlideLeft = 'l',        ///< a_n = 0, a_t > 0, c_n >= 0, c_t = -mu_k c_n; needs contact
  kSlideRight = 'r',       ///< a_n = 0, a_t < 0, c_n >= 0, c_t = mu_k c_n; needs contact
  kRoll = 'n',             ///< a_n = a_t = 0, |c_t| <= mu_s c_n; needs contact
  kMaintain = 'm',         ///< a_n = 0, |c_t| <= mu_s c_n; needs contact
  kSeparatePrinted = 'S',  ///< s as Table 2 prints it: a_n >= 0 also when touching, c = 0 (`--table2 printed`)
};

/// An augmented contact mode: one interaction per fixel, in fixel order.
struct ModeString {
  std::vector<Interaction> letters;
  std::string text() const;  ///< e.g. "na"
};

/// The sign constraint Table 2 puts on one element of y.
enum class SignConstraint { kFree, kZero, kNonNegative, kPositive, kNegative };

/// How Table 2 constrains the tangential force of a contact.
enum class FrictionConstraint { kZero, kStaticCone, kLeftEdge, kRightEdge };

/// Table 2's row for one letter, given whether the fixel touches.
struct InteractionConstraints {
  SignConstraint a_n, a_t, c_n;
  FrictionConstraint c_t;
};

/// Table 2, with the strict separation of a touching fixel (docs/papers.md errata).
InteractionConstraints table2(Interaction letter, bool touching);

/// Can this letter be used at a fixel that touches (l r n m s) or does not (a u s)?
bool letter_fits(Interaction letter, bool touching);

/// The letters of Table 2 that fit a touching or non-touching fixel, in the order s a u l r n m.
std::vector<Interaction> letters_for(bool touching);

enum class ModeStatus { kValid, kWrongLength, kUnknownLetter, kNeedsContact, kNeedsGap };

/// A parsed mode, or why the text is not a mode of the scene.
struct ModeParse {
  ModeStatus status = ModeStatus::kValid;
  ModeString mode;
  std::size_t fixel = 0;  ///< the offending fixel (0-based) when not kValid
  std::string message;    ///< what was expected, for the user
};

/// Parses a mode string against the touching state of each fixel (SPEC section 5); S is s as Table 2 prints it.
ModeParse parse_mode(std::string_view text, const std::vector<bool>& touching);

}  // namespace contactcert::solvers
