/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   Options the measuring modules share
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "module_options.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "util/parallel.hpp"

namespace sbrt_grass {

namespace {
constexpr uint64_t MB = uint64_t(1) << 20;
}

Option *define_memory(const char *description)
{
    Option *memory = G_define_standard_option(G_OPT_MEMORYMB);
    memory->description = description;
    return memory;
}

uint64_t memory_bytes_of(const char *text)
{
    char *end = nullptr;
    const double mb = std::strtod(text, &end);
    if (end == text || *end != '\0' || !(mb >= 1) || !(mb < 1e12))
        return 0;
    return uint64_t(mb * double(MB));
}

uint64_t read_memory(const Option *memory)
{
    if (!memory->answer)
        return 300 * MB;
    const uint64_t bytes = memory_bytes_of(memory->answer);
    if (!bytes)
        G_fatal_error(_("memory=%s is not a number of MB of at least 1"), memory->answer);
    return bytes;
}


Option *define_sbrt_option(const char *key, const char *description)
{
    Option *o = G_define_option();
    o->key = key;
    o->type = TYPE_STRING;
    o->key_desc = "name";
    o->required = YES;
    o->gisprompt = "old,sbrt,sbrt";
    o->description = description;
    return o;
}

Option *define_probability(const char *label)
{
    Option *o = G_define_option();
    o->key = "probability";
    o->type = TYPE_STRING;
    o->key_desc = "channel[+channel...]";
    o->required = NO;
    o->label = label;
    o->description = _("Property channels of the SBRT in %, one or a sum, e.g. "
                       "kans_5+kans_6+kans_7 (r3.sbrt.convert properties=)");
    o->guisection = _("Probability");
    return o;
}

Option *define_nprocs()
{
    Option *o = G_define_standard_option(G_OPT_M_NPROCS);
    o->answer = const_cast<char *>("0");
    o->description = _("Number of threads (0: all cores, a negative number: all but that "
                       "many)");
    return o;
}

unsigned read_nprocs(const Option *nprocs)
{
    return read_nprocs(nprocs->answer ? nprocs->answer : "0");
}

unsigned read_nprocs(const std::string &answer)
{
    const int threads = std::atoi(answer.c_str());
    if (threads > 0)
        return unsigned(threads);
    // as GRASS 8.4's G_set_omp_num_threads: 0 all cores, -n all but n
    const int cores = int(sbrt::thread_count(0));
    return unsigned(std::max(1, cores + threads));
}

std::vector<glm::dvec2> read_coordinate_pairs(const Option *coordinates)
{
    std::vector<glm::dvec2> pairs;
    if (coordinates->answers)
        for (int i = 0; coordinates->answers[i] && coordinates->answers[i + 1]; i += 2)
            pairs.push_back({std::strtod(coordinates->answers[i], nullptr),
                             std::strtod(coordinates->answers[i + 1], nullptr)});
    return pairs;
}

} // namespace sbrt_grass
