/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   Legends from and to GRASS
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "legend.hpp"

#include "model/material_table.hpp"
#include "raster_metadata.hpp"
#include "util/safe_text.hpp"

namespace sbrt_grass {

void read_raster3d_legend(const char *name, const char *mapset,
                          std::vector<sbrt::Material> &materials)
{
    struct Colors colors;
    const bool have_colors = Rast3d_read_colors(name, mapset, &colors) == 1;
    struct Categories cats;
    const bool have_cats = Rast3d_read_cats(name, mapset, &cats) == 0;
    for (size_t i = 1; i < materials.size(); ++i) {
        sbrt::Material &m = materials[i];
        CELL id = m.id;
        if (have_colors) {
            int r, g, b;
            Rast_get_c_color(&id, &r, &g, &b, &colors);
            m.red = uint8_t(r);
            m.green = uint8_t(g);
            m.blue = uint8_t(b);
            m.has_color = true;
        }
        if (have_cats && m.label.empty()) {
            const char *label = Rast_get_c_cat(&id, &cats);
            if (label)
                m.label = sbrt::valid_utf8(label);
        }
    }
    if (have_colors)
        Rast_free_colors(&colors);
    if (have_cats)
        Rast_free_cats(&cats);
}

void make_colors(const std::vector<sbrt::Material> &materials,
                 struct Colors *colors)
{
    Rast_init_colors(colors);
    for (size_t i = 1; i < materials.size(); ++i) {
        const auto rgb = sbrt::material_color(materials, uint32_t(i));
        CELL id = materials[i].id;
        Rast_add_c_color_rule(&id, rgb[0], rgb[1], rgb[2], &id, rgb[0], rgb[1],
                              rgb[2], colors);
    }
}

void make_cats(const std::vector<sbrt::Material> &materials,
               struct Categories *cats, const char *title)
{
    // each label and the title one line that GRASS reads back whole
    Rast_init_cats(metadata_line(title, MAX_TITLE_BYTES).c_str(), cats);
    for (size_t i = 1; i < materials.size(); ++i)
        if (!materials[i].label.empty()) {
            CELL id = materials[i].id;
            const std::string label = metadata_line(materials[i].label, MAX_LABEL_BYTES);
            Rast_set_c_cat(&id, &id, label.c_str(), cats);
        }
}

void write_class_legend(const char *name, const std::vector<sbrt::Material> &materials,
                        const char *title)
{
    struct Colors colors;
    make_colors(materials, &colors);
    Rast_write_colors(name, G_mapset(), &colors);
    Rast_free_colors(&colors);
    struct Categories cats;
    make_cats(materials, &cats, title);
    Rast_write_cats(name, &cats);
    Rast_free_cats(&cats);
}

} // namespace sbrt_grass
