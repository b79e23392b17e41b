/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The answers of a render request: each option's value (given
 *            or its default) and the flags set, read with clear errors.
 *            Made from the words of a command line or of a view server's
 *            request line (OptionTable::answer); nothing here touches
 *            GRASS's parser state
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_OPTION_ANSWERS_HPP
#define R3_SBRT_OPTION_ANSWERS_HPP

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

/// The words of a line as a POSIX shell splits them: blanks separate,
/// 'single' and "double" quotes and backslashes quote (what Python's
/// shlex.quote writes). Throws sbrt::Error on an unclosed quote.
std::vector<std::string> split_words(const std::string &line);

/// A value's parts at its commas, as G_parser splits answers.
std::vector<std::string> split_commas(const std::string &value);

/// \brief The options' values and the flags of one request.
class Answers {
public:
    Answers(std::map<std::string, std::string> values, std::string flags)
        : values_(std::move(values)), flags_(std::move(flags))
    {
    }

    /// Whether option `key` has a value (given, or a default).
    bool given(const char *key) const { return values_.count(key) != 0; }
    /// Its value, or `otherwise`.
    std::string text(const char *key, const char *otherwise = "") const;
    /// Its value's parts at commas (none without a value).
    std::vector<std::string> parts(const char *key) const;
    /// Its parts as numbers; throws naming the option otherwise.
    std::vector<double> numbers(const char *key) const;
    /// Its whole value as one finite number (the option has a value).
    double number(const char *key) const;
    /// x,y,z of a point option, if given.
    std::optional<glm::dvec3> point(const char *key) const;
    bool flag(char key) const { return flags_.find(key) != std::string::npos; }

private:
    std::map<std::string, std::string> values_;
    std::string flags_;
};

#endif
