/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Answers the module's options from a line of words
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "option_answers.hpp"

#include <cstdlib>
#include <cstring>
#include <sstream>

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

namespace {

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

/// Whether `value` is one of the choices of a string option ("a,b,c"),
/// or each of its numbers within the range of a numeric one ("-90-90"),
/// as G_parser checks.
bool allowed(const Option *option, const std::string &value)
{
    if (!option->options)
        return true;
    if (option->type == TYPE_STRING) {
        for (const std::string &choice : split_commas(option->options))
            if (choice == value)
                return true;
        return false;
    }
    const std::string range = option->options;
    const size_t dash = range.find('-', 1);
    if (dash == std::string::npos)
        return true;
    const double low = std::strtod(range.c_str(), nullptr),
                 high = std::strtod(range.c_str() + dash + 1, nullptr);
    for (const std::string &part : split_commas(value)) {
        char *end = nullptr;
        const double v = std::strtod(part.c_str(), &end);
        if (part.empty() || *end || !(v >= low && v <= high))
            return false;
    }
    return true;
}

} // namespace

OptionAnswers::OptionAnswers(Option *first_option, Flag *first_flag)
{
    for (Option *o = first_option; o; o = o->next_opt)
        options_.push_back(
            {o, o->answer ? std::optional<std::string>(o->answer) : std::nullopt});
    for (Flag *f = first_flag; f; f = f->next_flag)
        flags_.push_back(f);
}

void OptionAnswers::answer(const std::vector<std::string> &words)
{
    std::vector<std::optional<std::string>> given(options_.size());
    std::vector<char> flags(flags_.size(), 0);
    for (const std::string &word : words) {
        if (word.size() > 1 && word[0] == '-' && word[1] != '-') {
            for (size_t k = 1; k < word.size(); ++k) {
                size_t i = 0;
                while (i < flags_.size() && flags_[i]->key != word[k])
                    ++i;
                if (i == flags_.size())
                    sbrt::fail("unknown flag -" + shortened(std::string(1, word[k]), 8));
                flags[i] = 1;
            }
            continue;
        }
        const size_t equals = word.find('=');
        if (equals == std::string::npos || equals == 0)
            sbrt::fail("<" + shortened(word) + "> is neither key=value nor a -flag");
        const std::string key = word.substr(0, equals), value = word.substr(equals + 1);
        size_t i = 0;
        while (i < options_.size() && key != options_[i].option->key)
            ++i;
        if (i == options_.size())
            sbrt::fail("unknown option <" + shortened(key) + ">");
        if (value.empty())
            sbrt::fail(key + "=: give a value (or leave the option out)");
        if (given[i])
            sbrt::fail(key + "= is given twice; give each option once");
        if (!allowed(options_[i].option, value))
            sbrt::fail(key + "=" + shortened(value) + ": not " +
                       (options_[i].option->type == TYPE_STRING ? "one of " : "within ") +
                       options_[i].option->options);
        given[i] = value;
    }
    // the new answers point into new storage, then the old one goes
    std::vector<std::unique_ptr<std::string>> values;
    std::vector<std::unique_ptr<std::vector<char *>>> lists;
    for (size_t i = 0; i < options_.size(); ++i) {
        Option *o = options_[i].option;
        const std::optional<std::string> &answer = given[i] ? given[i] : options_[i].answer;
        o->answer = nullptr;
        o->answers = nullptr;
        if (!answer || answer->empty())
            continue;
        values.push_back(std::make_unique<std::string>(*answer));
        o->answer = values.back()->data();
        auto list = std::make_unique<std::vector<char *>>();
        for (const std::string &part : split_commas(*answer)) {
            values.push_back(std::make_unique<std::string>(part));
            list->push_back(values.back()->data());
        }
        list->push_back(nullptr);
        o->answers = list->data();
        lists.push_back(std::move(list));
    }
    for (size_t i = 0; i < flags_.size(); ++i)
        flags_[i]->answer = flags[i];
    values_ = std::move(values);
    lists_ = std::move(lists);
}
