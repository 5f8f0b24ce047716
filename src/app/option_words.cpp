// The command line's words before CLI11 parses them, and the messages for words it could not
// place: CLI11 takes any word after an option as its value and a short option's value straight
// after its letter, so FOSSSim checks and splits the words first (options.cpp then judges the
// values).
#include "option_words.h"

#include "fosssim/io/spelling.h"

#include <algorithm>
#include <cctype>

namespace fosssim::app {
namespace {

/// Every option's names as typed: "-s", "--threads".
std::vector<std::string> optionNames(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* opt : app.get_options()) {
    for (const std::string& s : opt->get_snames()) names.push_back("-" + s);
    for (const std::string& l : opt->get_lnames()) names.push_back("--" + l);
  }
  return names;
}

/// `word` names one of the options: "-q", "--threads", "--threads=2", "-d0" (a short option's
/// value may follow its letter).
bool isOptionWord(const std::string& word, const std::vector<std::string>& names) {
  if (word.size() < 2 || word[0] != '-') return false;
  for (const std::string& n : names) {
    if (n.size() == 2 && word[1] != '-' && word.compare(0, 2, n) == 0) return true;
    if (n.size() > 2 && word.compare(0, n.size(), n) == 0 && (word.size() == n.size() || word[n.size()] == '='))
      return true;
  }
  return false;
}

/// The option that `name` ("-o", "--movie") names when it takes a value; nullptr otherwise.
const CLI::Option* valueOption(const CLI::App& app, const std::string& name) {
  for (const CLI::Option* opt : app.get_options()) {
    if (opt->get_items_expected_min() == 0) continue;
    for (const std::string& s : opt->get_snames())
      if (name == "-" + s) return opt;
    for (const std::string& l : opt->get_lnames())
      if (name == "--" + l) return opt;
  }
  return nullptr;
}

}  // namespace

// Near misses only: an edit distance under 3 and shorter than the option, or a change of case.
std::string unknownWord(const CLI::App& app, const std::string& word) {
  const std::string hint = " (FOSSSim -h lists the options)";
  if (word.empty() || word[0] != '-' || word == "-")
    return "unexpected argument \"" + word + "\": the scene file is given with -s" + hint;
  const std::string name = word.substr(0, word.find('='));
  std::string best;
  size_t bestDistance = 3;  // suggest only near misses
  for (const std::string& candidate : optionNames(app)) {
    const auto d = static_cast<size_t>(io::editDistance(name, candidate));
    const bool otherCase = name.size() == candidate.size() && name != candidate &&
                           std::equal(name.begin(), name.end(), candidate.begin(),
                                      [](char a, char b) { return std::tolower(a) == std::tolower(b); });
    if ((d < bestDistance && d + 1 < candidate.size()) || otherCase) {  // "-D": -d; not "-x": -s
      bestDistance = d;
      best = candidate;
    }
  }
  return "unknown option \"" + word + "\"" + (best.empty() ? "" : " (did you mean " + best + "?)") + hint;
}

/// CLI11 gives a short option's value straight after its letter, so "-q=1" is the flag -q and
/// then "-=1", an unknown word: the word it came from names the flag. Empty for other words.
std::string shortFlagWithValue(const std::string& leftover, int argc, char** argv) {
  if (leftover.rfind("-=", 0) != 0) return "";
  const std::string value = leftover.substr(1);  // "=1"
  for (int k = 1; k < argc; ++k) {
    const std::string w = argv[k];
    if (w.size() > value.size() + 1 && w[0] == '-' && w[1] != '-' &&
        w.compare(w.size() - value.size(), value.size(), value) == 0)
      return "option -" + w.substr(w.size() - value.size() - 1, 1) + " takes no value";
  }
  return "";
}

/// The words with each "-X=value" of a short option that takes a value split into "-X" and
/// "value": CLI11 takes everything after the letter as the value, so "-o=out.bin" wrote a file
/// named "=out.bin" and "-d=0" was "takes 0 or 1, got \"=0\"", where "--threads=2" works.
std::vector<std::string> splitShortValues(const CLI::App& app, int argc, char** argv) {
  std::vector<std::string> words(argv, argv + argc);
  for (size_t k = words.size(); k-- > 1;) {
    const std::string w = words[k];
    if (w.size() < 3 || w[0] != '-' || w[1] == '-' || w[2] != '=') continue;
    for (const CLI::Option* opt : app.get_options())
      for (const std::string& s : opt->get_snames())
        if (s == w.substr(1, 1) && opt->get_items_expected_min() > 0) {
          words[k] = w.substr(0, 2);
          words.insert(words.begin() + static_cast<long>(k) + 1, w.substr(3));
        }
  }
  return words;
}

/// CLI11 takes the word after an option as its value whatever it is: "-o -i ref.bin" wrote the
/// trajectory to a file named "-i" (and "ref.bin" was then an unexpected argument), "-o -q" ran
/// without -q. A value given as the next word may not be an option; one given after '='
/// ("--movie=-m.mkv") is plainly a value. "-" names no file: "-o -" wrote a file named "-" where
/// the convention means standard output. `words` are argv as given.
std::string optionTakenAsValue(const CLI::App& app, const std::vector<std::string>& words) {
  const std::vector<std::string> names = optionNames(app);
  for (size_t k = 1; k < words.size(); ++k) {
    const std::string& w = words[k];
    const size_t equals = w.find('=');
    if (!valueOption(app, w.substr(0, equals))) continue;  // not an option, a flag, or "-d0" (its value joined)
    const bool joined = equals != std::string::npos;
    if (!joined && k + 1 == words.size()) break;  // no value: CLI11's error
    const std::string name = w.substr(0, equals), value = joined ? w.substr(equals + 1) : words[++k];
    if (!joined && (isOptionWord(value, names) || value == "--"))
      return "option " + name + " needs a value, and the next word \"" + value + "\" is " +
             (value == "--" ? "the end of the options" : "an option") + " (for a file of that name write ./" + value +
             ")";
    if (value == "-")
      return "option " + name + " takes a name, and \"-\" (standard input or output elsewhere) is none here: FOSSSim "
             "reads and writes named files only (for a file named - write ./-)";
  }
  return "";
}

/// "--" ends the options, as is conventional: CLI11 passed it on as a word, reported as unknown
/// option "--". FOSSSim takes nothing but options, so "--" may only end the command line; it is
/// removed from `words`. A "--" that is the value of the option before it is left alone. Returns
/// an error for a word after it, "" otherwise.
std::string endOfOptions(const CLI::App& app, std::vector<std::string>& words) {
  for (size_t k = 1; k < words.size(); ++k) {
    if (words[k] != "--") continue;
    const std::string& before = words[k - 1];
    if (k > 1 && before.find('=') == std::string::npos && valueOption(app, before)) continue;
    if (k + 1 < words.size())
      return "unexpected argument \"" + words[k + 1] + "\" after \"--\" (the end of the options): FOSSSim takes "
             "options only, the scene file is given with -s (FOSSSim -h lists the options)";
    words.erase(words.begin() + static_cast<long>(k));
    break;
  }
  return "";
}

}  // namespace fosssim::app
