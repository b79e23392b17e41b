/****************************************************************************
 * MODULE:    testsuite/fuzz (r3.sbrt addon)
 * PURPOSE:   Seed corpus of the reader's fuzz target: valid stacks files (v1, v2) of
 *            small random models and their `ranges` members (flag byte 1:
 *            checksums recomputed, and 0)
 * USAGE:     make_seeds DIR
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <fstream>
#include <iostream>
#include <string>

#include "format/column_ranges_file.hpp"
#include "format/column_tops_file.hpp"
#include "format/format.hpp"
#include "model/column_ranges.hpp"
#include "../unit/test_support.hpp"

int main(int argc, char **argv)
{
    if (argc != 2) {
        std::cerr << "usage: make_seeds DIR\n";
        return 2;
    }
    for (unsigned seed = 1; seed <= 4; ++seed) {
        const auto v = sbrt_test::random_voxels(seed, 2 + seed, 3 + seed, 6, 4);
        const sbrt::Model model = sbrt_test::build_model(v);
        sbrt::StacksV2Options blocks;
        blocks.block_size = 1 + int(seed % 3);
        const std::vector<uint8_t> v2 = sbrt::encode_stacks_v2(model, blocks);
        const sbrt::StacksStamp stamp = sbrt::stacks_stamp(v2.data(), v2.size(), "seed");
        sbrt::ColumnTopsEncoder tops(model.frame());
        tops.add(sbrt::column_tops(model));
        const std::vector<uint8_t> files[] = {
            sbrt::encode_stacks_v1(model), v2,
            // the `ranges` and `tops` members of those stacks (versions 3
            // and 4 in the name)
            sbrt::encode_column_ranges(sbrt::column_ranges(model), model.frame(), stamp),
            tops.finish(stamp)};
        for (int version = 1; version <= 4; ++version)
        for (uint8_t flag : {uint8_t(0), uint8_t(1)}) {
            const std::vector<uint8_t> &stacks = files[version - 1];
            std::ofstream out(std::string(argv[1]) + "/seed_v" + std::to_string(version) + "_" +
                                  std::to_string(seed) + "_" + std::to_string(flag),
                              std::ios::binary);
            out.put(char(flag));
            out.write(reinterpret_cast<const char *>(stacks.data()),
                      std::streamsize(stacks.size()));
        }
    }
    return 0;
}
