/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The module's options as the request's parts define them:
 *            GRASS's Option and Flag structs (for G_parser, the dialog and
 *            the manual) and, copied once from those definitions, what
 *            G_parser checks (choices, ranges, number types, values per
 *            answer, options given once), so that the command line's
 *            answers and a view server's request line are read by the same
 *            code without writing into GRASS's parser state
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_OPTION_TABLE_HPP
#define R3_SBRT_OPTION_TABLE_HPP

#include <optional>
#include <string>
#include <vector>

#include "grass.hpp"
#include "option_answers.hpp"

/// \brief What the checks need of one option, copied from its definition.
struct OptionInfo {
    std::string key;
    int type = TYPE_STRING;
    bool multiple = false;
    std::string choices;  ///< "a,b,c" (strings) or "low-high" (numbers); empty: any
    std::string key_desc; ///< e.g. "x,y,z": its commas + 1 values per answer
    std::optional<std::string> default_answer;
};

/// \brief The options and flags of the module.
class OptionTable {
public:
    /// An optional option of `type` in GUI section `section`.
    Option *define(const char *key, int type, const char *desc, const char *section,
                   const char *answer = nullptr);
    /// A string option with a fixed list of `choices` ("a,b") and their
    /// descriptions ("a;text;b;text") for the GUI.
    Option *define_choice(const char *key, const char *desc, const char *section,
                          const char *answer, const char *choices, const char *descriptions);
    /// An optional GRASS standard option (G_OPT_*) under its own `key`.
    Option *define_standard(STD_OPT kind, const char *key, const char *desc,
                            const char *section);
    Option *define_map_output(const char *key, const char *desc);
    Flag *define_flag(char key, const char *desc, const char *section);
    /// An option defined otherwise (G_define_standard_option as it is).
    Option *add(Option *option);

    /// After the last definition: what the checks need, copied.
    void seal();
    /// The option of `key` (defined), for the dialog's lists.
    Option *option(const char *key) const;

    /// The answers of `words` ("key=value", "-abc"), every option not given
    /// at its default. Throws sbrt::Error naming an unknown option or flag,
    /// an option given twice, an empty value, a value not among the
    /// option's choices or outside its range, not a number where the
    /// option takes numbers, or not a whole number of its key_desc's values.
    Answers answer(const std::vector<std::string> &words) const;
    /// The words of G_parser's answers (the command line as it parsed it).
    std::vector<std::string> parsed_words() const;

private:
    std::vector<Option *> options_;
    std::vector<Flag *> flags_;
    std::vector<OptionInfo> infos_;
    std::string flag_keys_;
};

#endif
