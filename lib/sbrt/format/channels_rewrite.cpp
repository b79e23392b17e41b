/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The `channels` member rewritten with new units and kinds
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "format/channels_rewrite.hpp"

#include <fcntl.h>
#include <unistd.h>

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
    std::string hist;
    for (const std::string &name : dir.member_names()) {
        if (name == "channels")
            continue;
        const FileDescriptor member = dir.open_regular(name); // no links, no FIFOs
        if (name == "hist") {
            const std::vector<uint8_t> bytes = read_all(member, dir.member_path(name));
            hist.assign(bytes.begin(), bytes.end());
            continue;
        }
        // the same inode: nothing ever writes into a member in place
        if (linkat(dir.fd(), name.c_str(), AT_FDCWD, out.file_path(name).c_str(), 0) != 0)
            out.copy_file(name, member, dir.member_path(name));
    }
    {
        FileSink sink(out.file_path("channels"));
        channels.write_with(infos, sink);
        sink.finish();
    }
    out.write_file("hist", hist + history);
    out.commit();
}

} // namespace sbrt
