/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The options of the module and the parse of a request, part by
 *            part (GUI sections as in m.nviz.image)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "render_options.hpp"

#include "util/error.hpp"

OptionTable define_render_options()
{
    OptionTable table;
    InputPart::define(table);
    OutputsPart::define(table);
    CameraPart::define(table);
    ExaggerationPart::define(table);
    ShadingPart::define(table);
    ColorsPart::define(table);
    StrataPart::define(table);
    SectionsPart::define(table);
    BoreholesPart::define(table);
    DrapePart::define(table);
    PropertyPart::define(table); // and SelectionPart's select=
    BackendPart::define(table);
    DetailPart::define(table);
    AnimationPart::define(table);
    // the command line's outputs (a view server's frame is its reply)
    G_option_required(table.option("output"), table.option("png"), table.option("value"),
                      NULL);
    G_option_requires(table.option("strds"), table.option("output"), NULL);
    table.seal();
    return table;
}

namespace {

/// The request of the answers; throws sbrt::Error (bad_request).
RenderRequest read_request(const Answers &answers)
{
    RenderRequest r;
    r.InputPart::read(answers);
    r.OutputsPart::read(answers);
    r.CameraPart::read(answers);
    r.ExaggerationPart::read(answers);
    r.ShadingPart::read(answers);
    r.ColorsPart::read(answers);
    r.StrataPart::read(answers);
    r.SectionsPart::read(answers);
    r.BoreholesPart::read(answers);
    r.DrapePart::read(answers);
    r.PropertyPart::read(answers);
    r.SelectionPart::read(answers);
    r.BackendPart::read(answers);
    r.DetailPart::read(answers);
    r.AnimationPart::read(answers);
    // what a part refuses of the others
    r.ShadingPart::check(r);
    r.AnimationPart::check(r, r);
    return r;
}

} // namespace

ParsedRequest parse_render_request(const OptionTable &options,
                                   const std::vector<std::string> &words)
{
    try {
        return {read_request(options.answer(words)), {}};
    }
    catch (const sbrt::Error &e) {
        return {std::nullopt, e.what()};
    }
}
