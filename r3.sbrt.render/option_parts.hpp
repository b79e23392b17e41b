/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Small helpers to define options (GUI sections) and to read
 *            their answers with clear errors
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_OPTION_PARTS_HPP
#define R3_SBRT_OPTION_PARTS_HPP

#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "grass.hpp"

namespace option_parts {

/// An optional option of `type` in GUI section `section`.
Option *define(const char *key, int type, const char *desc, const char *section,
               const char *answer = nullptr);
/// A string option with a fixed list of `choices` ("a,b") and their
/// descriptions ("a;text;b;text") for the GUI.
Option *define_choice(const char *key, const char *desc, const char *section,
                      const char *answer, const char *choices,
                      const char *descriptions);
/// An optional GRASS standard option (G_OPT_*) under its own `key`.
Option *define_standard(STD_OPT kind, const char *key, const char *desc,
                        const char *section);
Option *define_map_output(const char *key, const char *desc);
Flag *define_flag(char key, const char *desc, const char *section);

/// The answer of an optional option, or `otherwise`.
std::string answer_or(const Option *o, const char *otherwise = "");
/// Its answers as numbers; a fatal error naming the option otherwise.
std::vector<double> read_numbers(const Option *o);
/// x,y,z of a point option, if given.
std::optional<glm::dvec3> read_point(const Option *o);
double read_double(const Option *o);

} // namespace option_parts

#endif
