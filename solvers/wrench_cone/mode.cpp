#include "solvers/wrench_cone/mode.h"

namespace contactcert::solvers {

std::string ModeString::text() const {
  std::string s;
  for (Interaction l : letters) s += static_cast<char>(l);
  return s;
}

InteractionConstraints table2(Interaction letter, bool touching) {
  using S = SignConstraint;
  using F = FrictionConstraint;
  switch (letter) {
    case Interaction::kSeparate:
      return {touching ? S::kPositive : S::kNonNegative, S::kFree, S::kZero, F::kZero};
    case Interaction::kApproach:
      return {S::kNegative, S::kFree, S::kZero, F::kZero};
    case Interaction::kUnconstrained:
      return {S::kFree, S::kFree, S::kZero, F::kZero};
    case Interaction::kSlideLeft:
      return {S::kZero, S::kPositive, S::kNonNegative, F::kLeftEdge};
    case Interaction::kSlideRight:
      return {S::kZero, S::kNegative, S::kNonNegative, F::kRightEdge};
    case Interaction::kRoll:
      return {S::kZero, S::kZero, S::kNonNegative, F::kStaticCone};
    case Interaction::kMaintain:
      return {S::kZero, S::kFree, S::kNonNegative, F::kStaticCone};
    case Interaction::kSeparatePrinted:
      return {S::kNonNegative, S::kFree, S::kZero, F::kZero};
  }
  return {S::kFree, S::kFree, S::kZero, F::kZero};
}

bool letter_fits(Interaction letter, bool touching) {
  switch (letter) {
    case Interaction::kSeparate:
    case Interaction::kSeparatePrinted:
      return true;
    case Interaction::kApproach:
    case Interaction::kUnconstrained:
      return !touching;
    default:
      return touching;
  }
}

std::vector<Interaction> letters_for(bool touching) {
  std::vector<Interaction> out;
  for (char c : std::string_view("saulrnm")) {
    const auto l = static_cast<Interaction>(c);
    if (letter_fits(l, touching)) out.push_back(l);
  }
  return out;
}

ModeParse parse_mode(std::string_view text, const std::vector<bool>& touching) {
  ModeParse out;
  if (text.size() != touching.size()) {
    out.status = ModeStatus::kWrongLength;
    out.message = "one letter per fixel (" + std::to_string(touching.size()) + " letters from s a u l r n m), got " +
                  std::to_string(text.size());
    return out;
  }
  for (std::size_t i = 0; i < text.size(); ++i) {
    out.fixel = i;
    if (std::string_view("saulrnmS").find(text[i]) == std::string_view::npos) {
      out.status = ModeStatus::kUnknownLetter;
      out.message = "fixel " + std::to_string(i) + "'s letter '" + std::string(1, text[i]) +
                    "' is not one of s a u l r n m (or S)";
      return out;
    }
    const auto l = static_cast<Interaction>(text[i]);
    if (!letter_fits(l, touching[i])) {
      out.status = touching[i] ? ModeStatus::kNeedsGap : ModeStatus::kNeedsContact;
      out.message = "fixel " + std::to_string(i) + "'s letter '" + std::string(1, text[i]) + "': fixel " +
                    std::to_string(i) +
                    (touching[i] ? " touches, so use one of s l r n m" : " does not touch, so use one of s a u");
      return out;
    }
    out.mode.letters.push_back(l);
  }
  out.fixel = 0;
  return out;
}

}  // namespace contactcert::solvers
