/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Classic netCDF header -> the file length it declares
 *            (netCDF "File Format Specifications", classic and 64-bit
 *            offset formats; CDF-5 as PnetCDF defines it)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "builders/netcdf_classic.hpp"

#include <algorithm>
#include <cstring>
#include <limits>
#include <vector>

#include "util/error.hpp"

namespace sbrt {

namespace {

constexpr uint64_t MAX_U64 = std::numeric_limits<uint64_t>::max();
constexpr uint32_t NC_DIMENSION = 10, NC_VARIABLE = 11, NC_ATTRIBUTE = 12;

/// Thrown inside this file only: the header goes on past the prefix given.
struct PrefixEnds {
};

uint64_t add_sat(uint64_t a, uint64_t b)
{
    return a > MAX_U64 - b ? MAX_U64 : a + b;
}

uint64_t mul_sat(uint64_t a, uint64_t b)
{
    return a != 0 && b > MAX_U64 / a ? MAX_U64 : a * b;
}

uint64_t round4(uint64_t n)
{
    return n > MAX_U64 - 3 ? MAX_U64 : (n + 3) / 4 * 4;
}

/// Bytes of one value of nc_type `type`; 0 for a type the version lacks.
uint64_t type_bytes(uint64_t type, int version)
{
    static const uint64_t bytes[] = {0, 1, 1, 2, 4, 4, 8, 1, 2, 4, 8, 8};
    const uint64_t last = version == 5 ? 11 : 6;
    return type >= 1 && type <= last ? bytes[type] : 0;
}

/// \brief Big-endian fields of the header, each checked against the bytes
/// there are before it is read.
class HeaderReader {
public:
    HeaderReader(const uint8_t *data, size_t size, uint64_t file_bytes, int version)
        : data_(data), size_(std::min<uint64_t>(size, file_bytes)),
          file_bytes_(file_bytes), version_(version)
    {
    }

    uint64_t position() const { return pos_; }
    int version() const { return version_; }

    uint64_t u32(const char *what) { return read(4, what); }
    /// NON_NEG: 4 bytes, 8 in CDF-5.
    uint64_t non_neg(const char *what) { return read(version_ == 5 ? 8 : 4, what); }
    /// OFFSET: 4 bytes in CDF-1, else 8.
    uint64_t offset(const char *what) { return read(version_ == 1 ? 4 : 8, what); }

    void skip(uint64_t n, const char *what)
    {
        need(n, what);
        pos_ += n;
    }

    /// name = nelems namestring, padded to 4 bytes.
    std::string name(const char *what)
    {
        const uint64_t length = non_neg(what);
        const uint64_t start = pos_;
        skip(round4(length), what);
        return std::string(reinterpret_cast<const char *>(data_ + start), size_t(length));
    }

    [[noreturn]] void malformed(const std::string &what, uint64_t at) const
    {
        fail("netCDF classic header: ", what, " (at byte ", at, ")");
    }

private:
    void need(uint64_t n, const char *what) const
    {
        if (n <= size_ - pos_)
            return;
        if (size_ < file_bytes_)
            throw PrefixEnds();
        fail("netCDF classic header: ", what, " at byte ", pos_, " needs ",
             n == MAX_U64 ? std::string("more than 2^64") : std::to_string(n),
             " bytes, the file ends at byte ", file_bytes_,
             ": file is truncated inside its header");
    }

    uint64_t read(unsigned bytes, const char *what)
    {
        need(bytes, what);
        uint64_t v = 0;
        for (unsigned i = 0; i < bytes; ++i)
            v = v << 8 | data_[pos_ + i];
        pos_ += bytes;
        return v;
    }

    const uint8_t *data_;
    uint64_t size_, file_bytes_, pos_ = 0;
    int version_;
};

/// A list's tag and element count; 0 elements for ABSENT (ZERO ZERO).
uint64_t list_count(HeaderReader &in, uint32_t tag, const char *what)
{
    const uint64_t at = in.position();
    const uint64_t found = in.u32(what);
    const uint64_t count = in.non_neg(what);
    if (found == tag || (found == 0 && count == 0))
        return count;
    in.malformed(std::string(what) + ": tag " + std::to_string(found) +
                     " where " + std::to_string(tag) + " or an absent list (0 0) belongs",
                 at);
}

void skip_attributes(HeaderReader &in)
{
    const uint64_t count = list_count(in, NC_ATTRIBUTE, "attribute list");
    for (uint64_t i = 0; i < count; ++i) {
        in.name("attribute name");
        const uint64_t at = in.position();
        const uint64_t type = in.u32("attribute type");
        const uint64_t bytes = type_bytes(type, in.version());
        if (!bytes)
            in.malformed("attribute type " + std::to_string(type) + " is not a type of CDF-" +
                             std::to_string(in.version()),
                         at);
        const uint64_t values = in.non_neg("attribute length");
        in.skip(round4(mul_sat(values, bytes)), "attribute values");
    }
}

/// \brief A variable's data as the header places it.
struct VariableData {
    std::string name;
    bool record = false;
    uint64_t bytes = 0; ///< all of it, or one record's (unpadded)
    uint64_t begin = 0;
};

VariableData read_variable(HeaderReader &in, const std::vector<uint64_t> &dims,
                           int record_dim)
{
    VariableData v;
    v.name = in.name("variable name");
    const uint64_t rank = in.non_neg("variable rank");
    uint64_t values = 1;
    for (uint64_t d = 0; d < rank; ++d) {
        const uint64_t at = in.position();
        const uint64_t id = in.non_neg("dimension id");
        if (id >= dims.size())
            in.malformed("variable '" + v.name + "' names dimension " +
                             std::to_string(id) + " of " + std::to_string(dims.size()),
                         at);
        if (int64_t(id) == record_dim) {
            if (d != 0)
                in.malformed("variable '" + v.name +
                                 "' has the record dimension other than first",
                             at);
            v.record = true;
        }
        else
            values = mul_sat(values, dims[id]);
    }
    skip_attributes(in);
    const uint64_t at = in.position();
    const uint64_t type = in.u32("variable type");
    const uint64_t bytes = type_bytes(type, in.version());
    if (!bytes)
        in.malformed("variable '" + v.name + "' has type " + std::to_string(type) +
                         ", not a type of CDF-" + std::to_string(in.version()),
                     at);
    in.non_neg("variable size"); // vsize: redundant (and clipped in CDF-2)
    v.begin = in.offset("variable offset");
    v.bytes = mul_sat(values, bytes);
    return v;
}

/// Where the last record variable's data ends, given their layout.
void place_records(const std::vector<VariableData> &vars, uint64_t file_bytes,
                   ClassicLayout &layout)
{
    // records interleave every record variable, each padded to 4 bytes
    // unless there is only one (netCDF-C's NC_computeshapes)
    uint64_t record_bytes = 0, first_begin = MAX_U64, count = 0;
    for (const VariableData &v : vars)
        if (v.record) {
            record_bytes = add_sat(record_bytes, round4(v.bytes));
            first_begin = std::min(first_begin, v.begin);
            ++count;
        }
    if (count == 0)
        return;
    if (count == 1)
        for (const VariableData &v : vars)
            if (v.record)
                record_bytes = v.bytes;
    if (layout.streaming)
        layout.numrecs = record_bytes && file_bytes > first_begin
                             ? (file_bytes - first_begin) / record_bytes
                             : 0;
    if (layout.numrecs == 0)
        return;
    for (const VariableData &v : vars)
        if (v.record) {
            const uint64_t end =
                add_sat(add_sat(v.begin, mul_sat(layout.numrecs - 1, record_bytes)), v.bytes);
            if (end > layout.declared_bytes) {
                layout.declared_bytes = end;
                layout.last_variable = v.name;
            }
        }
}

ClassicLayout parse(HeaderReader &in, uint64_t file_bytes)
{
    ClassicLayout layout;
    layout.version = in.version();
    in.skip(4, "magic");
    layout.numrecs = in.non_neg("numrecs");
    layout.streaming = layout.numrecs == (in.version() == 5 ? MAX_U64 : 0xFFFFFFFFull);

    // dimensions: only one may be the record dimension (length 0)
    std::vector<uint64_t> dims;
    int record_dim = -1;
    const uint64_t dim_count = list_count(in, NC_DIMENSION, "dimension list");
    for (uint64_t i = 0; i < dim_count; ++i) {
        const uint64_t at = in.position();
        in.name("dimension name");
        const uint64_t length = in.non_neg("dimension length");
        if (length == 0) {
            if (record_dim >= 0)
                in.malformed("two record (unlimited) dimensions", at);
            record_dim = int(i);
        }
        dims.push_back(length);
    }
    skip_attributes(in);

    std::vector<VariableData> vars;
    const uint64_t var_count = list_count(in, NC_VARIABLE, "variable list");
    for (uint64_t i = 0; i < var_count; ++i)
        vars.push_back(read_variable(in, dims, record_dim));
    layout.header_bytes = in.position();

    // fixed-size variables: each its own block at begin
    layout.declared_bytes = layout.header_bytes;
    for (const VariableData &v : vars) {
        if (v.bytes == 0 || (v.record && layout.numrecs == 0 && !layout.streaming))
            continue;
        if (v.begin < layout.header_bytes)
            in.malformed("variable '" + v.name + "' begins at byte " +
                             std::to_string(v.begin) + ", inside the header (" +
                             std::to_string(layout.header_bytes) + " bytes)",
                         layout.header_bytes);
        const uint64_t end = add_sat(v.begin, v.bytes);
        if (!v.record && end > layout.declared_bytes) {
            layout.declared_bytes = end;
            layout.last_variable = v.name;
        }
    }
    place_records(vars, file_bytes, layout);
    return layout;
}

} // namespace

bool is_classic_netcdf(const uint8_t *data, size_t size)
{
    return size >= 4 && std::memcmp(data, "CDF", 3) == 0 &&
           (data[3] == 1 || data[3] == 2 || data[3] == 5);
}

std::optional<ClassicLayout> read_classic_layout(const uint8_t *data, size_t size,
                                                 uint64_t file_bytes)
{
    if (!is_classic_netcdf(data, std::min<uint64_t>(size, file_bytes)))
        fail("netCDF classic header: no magic CDF\\001, CDF\\002 or CDF\\005");
    HeaderReader in(data, size, file_bytes, data[3]);
    try {
        return parse(in, file_bytes);
    }
    catch (const PrefixEnds &) {
        return std::nullopt;
    }
}

void check_classic_length(const ClassicLayout &layout, uint64_t file_bytes,
                          const std::string &what)
{
    if (file_bytes >= layout.declared_bytes)
        return;
    fail(what, ": file is truncated: header declares ",
         layout.declared_bytes == MAX_U64 ? std::string("more than 2^64")
                                          : std::to_string(layout.declared_bytes),
         " bytes, file has ", file_bytes, " (variable '", layout.last_variable,
         "' ends past its end; the netCDF library would read zeros there). "
         "Copy or download the file again, whole");
}

} // namespace sbrt
