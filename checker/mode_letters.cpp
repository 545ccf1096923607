#include "checker/mode_letters.h"

namespace contactcert::checker {

std::string ModeAlphabet::letters(std::size_t fixel) const {
  const bool touches = touching.empty() || touching[fixel];
  std::string out = touches ? "slrn" : "sa";
  if (unions) out += touches ? 'm' : 'u';
  if (printed) out += 'S';
  return out;
}

std::string read_mode_letters(const exact::JsonInput& j, const ModeAlphabet& alphabet, std::size_t k, bool prefix) {
  const std::string text = j.string();
  if (text.size() > k || (prefix ? text.empty() : text.size() != k))
    j.fail(prefix ? "a mode prefix of 1 to " + std::to_string(k) + " letters"
                  : "one letter per fixel (" + std::to_string(k) + ")");
  for (std::size_t i = 0; i < text.size(); ++i) {
    const std::string letters = alphabet.letters(i);
    if (letters.find(text[i]) != std::string::npos) continue;
    std::string spelled;
    for (const char L : letters) spelled += std::string(spelled.empty() ? "" : " ") + L;
    j.fail("fixel " + std::to_string(i) + "'s letter '" + std::string(1, text[i]) +
           "' is not one of its letters in this alphabet (" + spelled + ")");
  }
  return text;
}

}  // namespace contactcert::checker
