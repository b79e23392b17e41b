/****************************************************************************
 * MODULE:    r3.sbrt.support
 * PURPOSE:   A rules file read whole before anything changes: a regular
 *            file of bounded size, or standard input for '-'; a FIFO, a
 *            device or a directory is refused at once instead of waited on
 *            or read without end (issue 48, item 6)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_SUPPORT_INPUT_FILE_HPP
#define R3_SBRT_SUPPORT_INPUT_FILE_HPP

#include <cstddef>
#include <string>

/// The largest rules file read (a legend of every class of a national
/// model is a few kilobytes).
constexpr size_t MAX_RULES_BYTES = size_t(16) << 20;

/// All of `file` (option `key`, e.g. "labels"), '-' for standard input;
/// G_fatal_error naming the option and the file where it is no regular
/// file, is over MAX_RULES_BYTES or cannot be read.
std::string read_rules_file(const char *key, const char *file);

#endif
