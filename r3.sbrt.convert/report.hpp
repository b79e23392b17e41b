/****************************************************************************
 * MODULE:    r3.sbrt.convert
 * PURPOSE:   What -p, -g and format= describe of an SBRT: from its decoded
 *            model, or from the block summaries of a format 2.1 file
 *            without decoding it (the same figures)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_CONVERT_REPORT_HPP
#define R3_SBRT_CONVERT_REPORT_HPP

#include <string>
#include <vector>

#include "format/format.hpp"
#include "model/model.hpp"
#include "output_format.hpp"

/// \brief The parts of a model a report prints (views of what outlives it).
struct ModelDescription {
    const sbrt::Frame &frame;
    const std::vector<sbrt::Material> &materials; ///< EMPTY first
    const std::string &vertical_datum;
    sbrt::Stats stats;
};

ModelDescription description_of(const sbrt::Model &model);
ModelDescription description_of(const sbrt::ModelSummary &summary);

/// print_report of a description (plain, shell or json).
void print_description(const char *name, const ModelDescription &model,
                       const sbrt::StacksFileInfo &file, sbrt_grass::OutputFormat format,
                       const sbrt::PropertyChannels *channels = nullptr);
/// print_report_json of a description.
void print_description_json(const char *name, const ModelDescription &model,
                            const sbrt::StacksFileInfo &file,
                            const sbrt::PropertyChannels *channels);

#endif
