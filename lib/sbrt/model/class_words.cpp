/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The words that name classes: trimmed, compared, class ids
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "model/class_words.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>

#include "model/model.hpp" // NULL_CLASS

namespace sbrt {

std::string trim(const std::string &text)
{
    const auto first = text.find_first_not_of(" \t\r\n");
    if (first == std::string::npos)
        return "";
    return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}

bool same_text(const std::string &a, const std::string &b)
{
    return a.size() == b.size() &&
           std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) ==
                      std::tolower(static_cast<unsigned char>(y));
           });
}

bool parse_class_id(const std::string &text, int32_t &id)
{
    const std::string t = trim(text);
    if (t.empty())
        return false;
    char *end = nullptr;
    errno = 0;
    const long long value = std::strtoll(t.c_str(), &end, 10);
    if (errno == ERANGE || *end != '\0' || value < INT32_MIN || value > INT32_MAX ||
        value == NULL_CLASS)
        return false;
    id = int32_t(value);
    return true;
}

} // namespace sbrt
