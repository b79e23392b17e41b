/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   A render request's model: input= and its colours (color=, rules=),
 *            what the session's model stage reads (part of its key)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_INPUT_PART_HPP
#define R3_SBRT_INPUT_PART_HPP

#include <cstdint>
#include <string>

#include "option_table.hpp"

struct RenderRequest;

/// \brief input=: the SBRT to render; memory=: the most its decoded blocks
/// take where the CPU reads them as rays reach them (a paged model).
struct InputPart {
    static constexpr uint64_t DEFAULT_MEMORY = uint64_t(300) << 20; ///< GRASS's 300 MB
    std::string input;
    uint64_t memory_bytes = DEFAULT_MEMORY;
    /// memory= given: a model that needs more is refused, not decoded whole
    bool memory_given = false;

    static void define(OptionTable &table);
    void read(const Answers &answers);
    /// What the model as read depends on.
    std::string key() const;
};

/// \brief color= and rules=: the classes' colours instead of the stored ones.
struct ColorsPart {
    std::string color, rules; ///< colour table name or rules file

    static void define(OptionTable &table);
    void read(const Answers &answers);
    std::string key() const;
};

/// A map name of option `key`: GRASS's look-ups copy names into buffers of
/// GNAME_MAX bytes (a longer name crashed G_find_file2), so a longer one is
/// refused here.
void check_map_name(const char *key, const std::string &name);

#endif
