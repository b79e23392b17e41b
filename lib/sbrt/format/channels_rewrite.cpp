/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The `channels` member rewritten with new units and kinds
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "format/channels_rewrite.hpp"


#include "format/atomic_dir.hpp"
#include "format/byte_sink.hpp"
#include "format/member_dir.hpp"
#include "util/error.hpp"

namespace sbrt {

void rewrite_channels(const std::string &directory, const PropertyChannels &channels,
                      const std::vector<ChannelInfo> &infos, const std::string &history)
{
    const MemberDirectory dir(directory);
    AtomicDirectory out(directory);
    const std::string hist = stage_other_members(dir, out, {"channels"});
    {
        FileSink sink(out.file_path("channels"));
        channels.write_with(infos, sink);
        sink.finish();
    }
    out.write_file("hist", hist + history);
    out.commit();
}

} // namespace sbrt
