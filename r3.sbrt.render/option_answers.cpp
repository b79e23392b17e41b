/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The answers of a render request
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "option_answers.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "grass.hpp"
#include "request_error.hpp"
#include "util/error.hpp"

std::vector<std::string> split_words(const std::string &line)
{
    std::vector<std::string> words;
    std::string word;
    bool in_word = false;
    for (size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
            if (in_word)
                words.push_back(word);
            word.clear();
            in_word = false;
            continue;
        }
        in_word = true;
        if (c == '\\' && i + 1 < line.size()) {
            word += line[++i];
        }
        else if (c == '\'' || c == '"') {
            const size_t end = line.find(c, i + 1);
            if (end == std::string::npos)
                sbrt::fail("unclosed quote " + std::string(1, c) + " in: " + shortened(line));
            std::string quoted = line.substr(i + 1, end - i - 1);
            if (c == '"') { // \" and \\ within double quotes
                std::string plain;
                for (size_t k = 0; k < quoted.size(); ++k)
                    plain += quoted[k] == '\\' && k + 1 < quoted.size() ? quoted[++k]
                                                                        : quoted[k];
                quoted = plain;
            }
            word += quoted;
            i = end;
        }
        else {
            word += c;
        }
    }
    if (in_word)
        words.push_back(word);
    return words;
}

std::vector<std::string> split_commas(const std::string &value)
{
    std::vector<std::string> parts;
    std::istringstream in(value);
    std::string part;
    while (std::getline(in, part, ','))
        parts.push_back(part);
    if (!value.empty() && value.back() == ',')
        parts.emplace_back();
    return parts;
}

std::string Answers::text(const char *key, const char *otherwise) const
{
    const auto found = values_.find(key);
    return found == values_.end() ? otherwise : found->second;
}

std::vector<std::string> Answers::parts(const char *key) const
{
    return given(key) ? split_commas(text(key)) : std::vector<std::string>();
}

std::vector<double> Answers::numbers(const char *key) const
{
    std::vector<double> values;
    for (const std::string &part : parts(key)) {
        char *end = nullptr;
        const double v = std::strtod(part.c_str(), &end);
        if (part.empty() || *end || !std::isfinite(v))
            bad_request(_("Option <%s>: <%s> is not a number"), key,
                        shortened(part, 100).c_str());
        values.push_back(v);
    }
    return values;
}

double Answers::number(const char *key) const
{
    const std::string value = text(key);
    char *end = nullptr;
    const double v = std::strtod(value.c_str(), &end);
    if (value.empty() || *end || !std::isfinite(v))
        bad_request(_("Option <%s>: <%s> is not a number"), key,
                    shortened(value, 100).c_str());
    return v;
}

std::optional<glm::dvec3> Answers::point(const char *key) const
{
    if (!given(key))
        return std::nullopt;
    const std::vector<double> v = numbers(key);
    if (v.size() != 3)
        bad_request(_("Option <%s> needs three values x,y,z"), key);
    return glm::dvec3(v[0], v[1], v[2]);
}
