/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The view server's reply lines that quote texts it did not
 *            write: a model's legend (the "classes" reply: a class's id,
 *            colour and label, a channel's range and name|unit|long name,
 *            from the SBRT, which may be another user's) and an error (which
 *            may quote a request's values). Each is one line of valid UTF-8
 *            with no control character; a channel's fields never hold '|'
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_REPLY_LINES_HPP
#define R3_SBRT_REPLY_LINES_HPP

#include <array>
#include <cstdint>
#include <string>

#include "model/model.hpp"
#include "model/property_channel.hpp"

/// "id red green blue label\n" of class `material` drawn in `rgb`.
std::string class_reply_line(const sbrt::Material &material,
                             const std::array<uint8_t, 3> &rgb);

/// "least greatest name|unit|long name\n" of channel `info` (the values
/// as meant: scale and offset applied).
std::string channel_reply_line(const sbrt::ChannelInfo &info);

/// "error message\n": `message` cut to a readable length, line breaks
/// as spaces, printable.
std::string error_reply_line(const std::string &message);

#endif
