#pragma once
// The command line's words before CLI11 parses them (option_words.cpp says why each check exists).
// Each check returns "" when the words are fine, otherwise the message for the user.

#include "cli_values.h"

#include <string>
#include <vector>

namespace fosssim::app {

/// The message for a word CLI11 could not place: an unknown option (with the nearest option's
/// name when it is a near miss or differs only in case) or a stray argument.
std::string unknownWord(const CLI::App& app, const std::string& word);

/// For a leftover word that came from "-q=1" (a flag given a value), the message naming the flag;
/// "" for other words.
std::string shortFlagWithValue(const std::string& leftover, int argc, char** argv);

/// argv with each "-X=value" of a short option that takes a value split into "-X" and "value".
std::vector<std::string> splitShortValues(const CLI::App& app, int argc, char** argv);

/// An option word given as the value of the option before it ("-o -i ref.bin"), or "-" given as
/// a file name: the message; "" otherwise.
std::string optionTakenAsValue(const CLI::App& app, const std::vector<std::string>& words);

/// Removes a final "--" from `words`; the message for a word after one, "" otherwise.
std::string endOfOptions(const CLI::App& app, std::vector<std::string>& words);

}  // namespace fosssim::app
