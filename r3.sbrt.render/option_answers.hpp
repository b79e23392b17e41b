/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Answers the module's options from a line of words, as the
 *            command line would (key=value and -flags), again and again:
 *            the view server reads one request per line with the same
 *            validation as the command line (read_render_options)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_OPTION_ANSWERS_HPP
#define R3_SBRT_OPTION_ANSWERS_HPP

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "grass.hpp"

/// The words of a line as a POSIX shell splits them: blanks separate,
/// 'single' and "double" quotes and backslashes quote (what Python's
/// shlex.quote writes). Throws sbrt::Error on an unclosed quote.
std::vector<std::string> split_words(const std::string &line);

/// \brief The options and flags defined after (and with) `first_option`
/// and `first_flag`, their defaults kept, answered from words.
class OptionAnswers {
public:
    OptionAnswers(Option *first_option, Flag *first_flag);
    OptionAnswers(const OptionAnswers &) = delete;
    OptionAnswers &operator=(const OptionAnswers &) = delete;

    /// Every option back to its default and every flag off, then the
    /// answers of `words` ("key=value", "-abc"), split at commas into
    /// `answers` as G_parser does. Throws sbrt::Error naming an unknown
    /// option or flag, an empty value, or a value not among an option's
    /// choices or outside its range.
    void answer(const std::vector<std::string> &words);

private:
    struct Default {
        Option *option;
        std::optional<std::string> answer;
    };
    std::vector<Default> options_;
    std::vector<Flag *> flags_;
    // what the options' answer and answers point into, until the next answer()
    std::vector<std::unique_ptr<std::string>> values_;
    std::vector<std::unique_ptr<std::vector<char *>>> lists_;
};

#endif
