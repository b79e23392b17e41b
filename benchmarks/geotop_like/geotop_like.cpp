/****************************************************************************
 * MODULE:    benchmarks/geotop_like (r3.sbrt addon)
 * PURPOSE:   Writes a deterministic GeoTOP-like NetCDF file of any size
 *            (lithoclass int16 'lithok' (x, y, z), z fastest, 100 m x 100 m
 *            x 0.5 m, _FillValue -127, deflate-compressed chunks), band by
 *            band of rows, with the layout of TNO's GeoTOP v01r6 files
 *            (issue 31, item 7): their global title, institution and
 *            source, Dutch long_names, no flag_values/flag_meanings,
 *            epsg = "7415" (RD New + NAP) on the coordinate variables and
 *            no grid_mapping, z with standard_name depth but positive up
 *            (m relative to NAP). With `properties` also GeoTOP's
 *            per-voxel channels (issue 29): kans_1 ... kans_9, the
 *            probability in percent of each lithoclass (integers summing to
 *            100 in every valid voxel, 0 in class-0 voxels, kans_4 0
 *            everywhere), onz_lk = round(100 H(p) / ln K) (K the classes
 *            possible in the voxel's unit) and onz_ls (0..30), int16 with
 *            _FillValue -127, on the same dims, Dutch long_names and no
 *            units, as TNO delivers them (issue 51). Or reads the
 *            variables once through the netCDF library (the import's
 *            baseline)
 * USAGE:     geotop_like write FILE NX NY NZ [properties] |
 *            geotop_like read FILE [VARIABLE...]
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <netcdf.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <algorithm>
#include <vector>

namespace {

constexpr short FILL = -127;
constexpr int LAYERS = 30;   // layer boundaries per column, some merge
constexpr size_t CHUNK = 16; // chunk of 16 x 16 whole columns
// GeoTOP's lithoclasses (4 is not used)
constexpr short LITHOCLASSES[9] = {0, 1, 2, 3, 5, 6, 7, 8, 9};

void check(int status, const char *what)
{
    if (status != NC_NOERR) {
        std::fprintf(stderr, "geotop_like: %s: %s\n", what, nc_strerror(status));
        std::exit(1);
    }
}

/// Deterministic noise in [0, 1) of integer coordinates.
double noise(uint64_t a, uint64_t b, uint64_t c)
{
    uint64_t h = a * 0x9E3779B97F4A7C15ull ^ (b + 0x632BE59BD9B4E019ull) * 0xC2B2AE3D27D4EB4Full ^
                 (c + 1) * 0x165667B19E3779F9ull;
    h ^= h >> 31;
    h *= 0xD6E8FEB86659FD93ull;
    h ^= h >> 32;
    return double(h >> 11) / double(1ull << 53);
}

/// Whether (i, j) lies on land: a country-like blob inside the box.
bool on_land(size_t i, size_t j, size_t nx, size_t ny)
{
    const double u = double(i) / nx - 0.5, v = double(j) / ny - 0.5;
    const double r = 0.42 + 0.05 * std::sin(9 * std::atan2(v, u)) +
                     0.03 * std::sin(23 * u + 7 * v);
    return u * u + v * v < r * r && !(u < -0.25 && v > 0.3);
}

/// The column (z from the bottom) of cell (i, j): layers of lithoclasses
/// 0-9 (no 4) whose boundaries undulate smoothly, fill above the ground
/// level; `layers` (where given) gets each voxel's layer.
void column(size_t i, size_t j, size_t nz, short *out, short *layers = nullptr)
{
    const double x = double(i), y = double(j);
    const double ground = nz * (0.82 + 0.08 * std::sin(x / 211) * std::cos(y / 173)) +
                          2 * noise(i, j, 0);
    size_t z = 0;
    for (int layer = 0; layer < LAYERS && z < nz; ++layer) {
        const double mean = ground / LAYERS;
        double top = (layer + 1) * mean +
                     0.6 * mean * std::sin(x / (47 + 7 * layer) + layer) *
                         std::cos(y / (61 + 5 * layer) - layer);
        if (layer == LAYERS - 1 || top > ground)
            top = ground;
        const short cls = LITHOCLASSES[(layer * 7 + int(x / 400) + int(y / 300) +
                                        int(3 * noise(i / 8, j / 8, layer))) % 9];
        for (; z < nz && double(z) < top; ++z) {
            out[z] = cls;
            if (layers)
                layers[z] = short(layer);
        }
    }
    for (; z < nz; ++z)
        out[z] = FILL;
}

constexpr int PROPERTIES = 11; // kans_1 ... kans_9, onz_lk, onz_ls
const char *const PROPERTY_NAMES[PROPERTIES] = {
    "kans_1", "kans_2", "kans_3", "kans_4", "kans_5", "kans_6",
    "kans_7", "kans_8", "kans_9", "onz_lk", "onz_ls"};
/// The lithoclasses possible in a unit (4 of the 8 with a probability).
constexpr int POSSIBLE = 4;

/// The eleven channels of one column, `props[p * nz + z]`: percentages from
/// smooth weights of the classes possible in the voxel's layer (the class
/// of lithok weighted most, so that it is not the most probable in some
/// voxels only), rounded by largest remainders to sum to exactly 100.
void property_column(size_t i, size_t j, size_t nz, const short *classes,
                     const short *layers, short *props)
{
    static const short candidates[8] = {1, 2, 3, 5, 6, 7, 8, 9};
    const double x = double(i), y = double(j);
    for (size_t z = 0; z < nz; ++z) {
        short *at[PROPERTIES];
        for (int p = 0; p < PROPERTIES; ++p)
            at[p] = props + size_t(p) * nz + z;
        if (classes[z] == FILL) {
            for (int p = 0; p < PROPERTIES; ++p)
                *at[p] = FILL;
            continue;
        }
        const int layer = layers[z];
        *at[10] = short(std::lround(15 + 15 * std::sin(z / 9.0 + x / 97 + layer) *
                                             std::cos(y / 83 - 0.3 * layer)));
        if (classes[z] == 0) { // anthropogenic: no lithoclass probabilities
            for (int p = 0; p < 10; ++p)
                *at[p] = 0;
            continue;
        }
        // the classes possible in this layer: lithok's and three others
        int classes_of_unit[POSSIBLE];
        double weight[POSSIBLE];
        classes_of_unit[0] = classes[z];
        for (int k = 1, c = layer; k < POSSIBLE; ++c) {
            const short candidate = candidates[(c * 3 + k) % 8];
            bool taken = false;
            for (int m = 0; m < k; ++m)
                taken |= classes_of_unit[m] == candidate;
            if (!taken)
                classes_of_unit[k++] = candidate;
        }
        double sum = 0;
        for (int k = 0; k < POSSIBLE; ++k) {
            const double wave = std::sin(z / (5.0 + 3 * k) + x / (53.0 + 11 * k) + k) *
                                std::cos(y / (67.0 + 7 * k) - 2 * k);
            weight[k] = k == 0 ? 1.8 + 1.0 * wave : std::max(0.0, 0.45 + 0.9 * wave);
            sum += weight[k];
        }
        int percent[POSSIBLE], total = 0;
        double remainder[POSSIBLE];
        for (int k = 0; k < POSSIBLE; ++k) {
            const double exact = 100 * weight[k] / sum;
            percent[k] = int(exact);
            remainder[k] = exact - percent[k];
            total += percent[k];
        }
        for (; total < 100; ++total) { // largest remainders get the rest
            int best = 0;
            for (int k = 1; k < POSSIBLE; ++k)
                if (remainder[k] > remainder[best])
                    best = k;
            ++percent[best];
            remainder[best] = -1;
        }
        for (int p = 0; p < 9; ++p)
            *at[p] = 0;
        double entropy = 0;
        for (int k = 0; k < POSSIBLE; ++k) {
            *at[classes_of_unit[k] - 1] = short(percent[k]);
            if (percent[k] > 0)
                entropy -= percent[k] / 100.0 * std::log(percent[k] / 100.0);
        }
        *at[9] = short(std::lround(100 * entropy / std::log(double(POSSIBLE))));
    }
}

int write_file(const char *path, size_t nx, size_t ny, size_t nz, bool properties)
{
    int nc, dx, dy, dz, vx, vy, vz, vl, vp[PROPERTIES];
    check(nc_create(path, NC_NETCDF4 | NC_CLOBBER, &nc), path);
    check(nc_def_dim(nc, "x", nx, &dx), "x");
    check(nc_def_dim(nc, "y", ny, &dy), "y");
    check(nc_def_dim(nc, "z", nz, &dz), "z");
    check(nc_def_var(nc, "x", NC_INT, 1, &dx, &vx), "x");
    check(nc_def_var(nc, "y", NC_INT, 1, &dy, &vy), "y");
    check(nc_def_var(nc, "z", NC_FLOAT, 1, &dz, &vz), "z");
    const int dims[3] = {dx, dy, dz};
    const size_t chunks[3] = {CHUNK, CHUNK, nz};
    auto define = [&](const char *name, int *var) {
        check(nc_def_var(nc, name, NC_SHORT, 3, dims, var), name);
        check(nc_def_var_chunking(nc, *var, NC_CHUNKED, chunks), "chunking");
        check(nc_def_var_deflate(nc, *var, 1, 1, 1), "deflate");
        check(nc_def_var_fill(nc, *var, 0, &FILL), "fill");
        check(nc_put_att_short(nc, *var, "missing_value", NC_SHORT, 1, &FILL), "att");
    };
    auto text = [&](int var, const char *key, const std::string &value) {
        check(nc_put_att_text(nc, var, key, value.size(), value.c_str()), key);
    };
    define("lithok", &vl);
    for (int p = 0; properties && p < PROPERTIES; ++p) {
        define(PROPERTY_NAMES[p], &vp[p]);
        // as TNO delivers them (issue 51): a Dutch long_name, no units
        if (p < 9)
            text(vp[p], "long_name", "kans op lithoklasse " + std::to_string(p + 1));
        else
            text(vp[p], "long_name", p == 9 ? "onzekerheid lithoklasse"
                                            : "onzekerheid stratigrafische eenheid");
    }
    // as GeoTOP v01r6 (issue 31): the CRS only as epsg on the coordinates
    text(vx, "standard_name", "projection_x_coordinate");
    text(vx, "long_name", "x-coordinaat");
    text(vx, "units", "m");
    text(vx, "epsg", "7415");
    text(vy, "standard_name", "projection_y_coordinate");
    text(vy, "long_name", "y-coordinaat");
    text(vy, "units", "m");
    text(vy, "epsg", "7415");
    text(vz, "standard_name", "depth");
    text(vz, "long_name", "diepte t.o.v. NAP");
    text(vz, "positive", "up");
    text(vz, "units", "m");
    text(vz, "epsg", "7415");
    text(vl, "long_name", "meest waarschijnlijke lithoklasse");
    text(NC_GLOBAL, "Conventions", "CF-1.4");
    text(NC_GLOBAL, "title", "geotop v01r6 (100.0m * 100.0m * 0.5m");
    text(NC_GLOBAL, "institution", "TNO / Geologische Dienst Nederland");
    text(NC_GLOBAL, "source",
         "Generated by nl.tno.dino.geo3dmodel.generator.GeoTOPVoxelModelGenerator");
    check(nc_enddef(nc), "enddef");

    std::vector<int> xs(nx), ys(ny);
    std::vector<float> zs(nz);
    for (size_t i = 0; i < nx; ++i)
        xs[i] = int(13650 + 100 * i);
    for (size_t j = 0; j < ny; ++j)
        ys[j] = int(306050 + 100 * j);
    for (size_t k = 0; k < nz; ++k)
        zs[k] = float(-49.75 + 0.5 * k);
    check(nc_put_var_int(nc, vx, xs.data()), "x");
    check(nc_put_var_int(nc, vy, ys.data()), "y");
    check(nc_put_var_float(nc, vz, zs.data()), "z");

    // bands of CHUNK rows of y: whole chunks per write
    std::vector<short> band(nx * CHUNK * nz), layers(nz), props(PROPERTIES * nz);
    std::vector<short> prop_bands(properties ? PROPERTIES * band.size() : 0);
    for (size_t j0 = 0; j0 < ny; j0 += CHUNK) {
        const size_t rows = std::min(CHUNK, ny - j0);
        for (size_t i = 0; i < nx; ++i)
            for (size_t j = 0; j < rows; ++j) {
                const size_t at = (i * rows + j) * nz;
                short *out = band.data() + at;
                if (on_land(i, j0 + j, nx, ny))
                    column(i, j0 + j, nz, out, layers.data());
                else
                    std::fill(out, out + nz, FILL);
                if (!properties)
                    continue;
                property_column(i, j0 + j, nz, out, layers.data(), props.data());
                for (int p = 0; p < PROPERTIES; ++p)
                    std::copy(props.begin() + p * nz, props.begin() + (p + 1) * nz,
                              prop_bands.begin() + p * band.size() + at);
            }
        const size_t start[3] = {0, j0, 0}, count[3] = {nx, rows, nz};
        check(nc_put_vara_short(nc, vl, start, count, band.data()), "write");
        for (int p = 0; properties && p < PROPERTIES; ++p)
            check(nc_put_vara_short(nc, vp[p], start, count,
                                    prop_bands.data() + p * band.size()),
                  "write");
    }
    check(nc_close(nc), "close");
    return 0;
}

/// Reads `variables` once, band by band, as the import does.
int read_file(const char *path, const std::vector<std::string> &variables)
{
    const auto t0 = std::chrono::steady_clock::now();
    int nc, dims[3];
    check(nc_open(path, NC_NOWRITE, &nc), path);
    std::vector<int> vars;
    for (const std::string &name : variables) {
        vars.push_back(0);
        check(nc_inq_varid(nc, name.c_str(), &vars.back()), name.c_str());
    }
    check(nc_inq_vardimid(nc, vars[0], dims), "dims");
    size_t n[3];
    for (int d = 0; d < 3; ++d)
        check(nc_inq_dimlen(nc, dims[d], &n[d]), "dim");
    std::vector<short> band(n[0] * CHUNK * n[2]);
    uint64_t sum = 0;
    for (size_t j0 = 0; j0 < n[1]; j0 += CHUNK) {
        const size_t rows = std::min(CHUNK, n[1] - j0);
        const size_t start[3] = {0, j0, 0}, count[3] = {n[0], rows, n[2]};
        for (int var : vars) {
            check(nc_get_vara_short(nc, var, start, count, band.data()), "read");
            for (size_t k = 0; k < n[0] * rows * n[2]; ++k)
                sum += uint16_t(band[k]);
        }
    }
    check(nc_close(nc), "close");
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("read_once_s=%.3f voxels=%llu checksum=%llu\n", s,
                (unsigned long long)(n[0] * n[1] * n[2]), (unsigned long long)sum);
    return 0;
}

} // namespace

int main(int argc, char **argv)
{
    const bool properties = argc == 7 && std::string(argv[6]) == "properties";
    if ((argc == 6 || properties) && std::string(argv[1]) == "write")
        return write_file(argv[2], std::strtoul(argv[3], nullptr, 10),
                          std::strtoul(argv[4], nullptr, 10),
                          std::strtoul(argv[5], nullptr, 10), properties);
    if (argc >= 3 && std::string(argv[1]) == "read") {
        std::vector<std::string> variables(argv + 3, argv + argc);
        if (variables.empty())
            variables.push_back("lithok");
        return read_file(argv[2], variables);
    }
    std::fprintf(stderr, "usage: geotop_like write FILE NX NY NZ [properties] | "
                         "geotop_like read FILE [VARIABLE...]\n");
    return 2;
}
