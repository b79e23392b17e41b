# Sourced inside a GRASS session by the benchmark scripts:
#   bench_model SIZE TOOLS_DIR
# makes the demo model geo_SIZE where the search path lacks it, converts
# it to an SBRT where none exists, sets map= and sbrt= (the SBRT's
# directory) and the region to the model at 1056 x 884 pixels.
# The code that writes an SBRT's files, as git names its committed trees
# (a change of a reader there counts too; uncommitted edits do not): a
# benchmark model imported by other code is imported again (a model
# written before its members were framed decoded them on one core, and
# every figure measured that).
bench_writer_stamp() {
    git -C "$1/.." rev-parse HEAD:lib/sbrt/format HEAD:lib/sbrt/builders HEAD:r3.sbrt.convert \
        2>/dev/null | tr '\n' ' '
}
# Whether the SBRT directory $1 was written by the code at hand (its stamp,
# beside it, names that code).
bench_sbrt_current() {
    [ "$(cat "$(dirname "$1")/.$(basename "$1").writer" 2>/dev/null)" = "$(bench_writer_stamp "$2")" ]
}
bench_sbrt_stamp() {
    bench_writer_stamp "$2" >"$(dirname "$1")/.$(basename "$1").writer"
}
bench_model() {
    local size=$1 tools=$2 loc m
    map=geo_$size
    [ -n "$(g.list type=raster_3d pattern="$map")" ] || "$tools/make_geomodel.sh" "$size" "$map" >/dev/null
    loc=$(g.gisenv get=GISDBASE)/$(g.gisenv get=LOCATION_NAME)
    sbrt=""
    for m in $(g.mapsets -p sep=space); do
        [ -e "$loc/$m/sbrt/$map" ] && { sbrt=$loc/$m/sbrt/$map; break; }
    done
    if [ -z "$sbrt" ] || ! bench_sbrt_current "$sbrt" "$tools"; then
        r3.sbrt.convert --q --o input="$map" output="$map" || return 1
        sbrt=$loc/$(g.gisenv get=MAPSET)/sbrt/$map
        bench_sbrt_stamp "$sbrt" "$tools"
    fi
    g.region --q raster_3d="$map"
    g.region --q rows=884 cols=1056
}

#   geotop_bench_model NX NY NZ DATA_DIR TOOLS_DIR [3D]
# makes the GeoTOP-like NetCDF model of NX x NY x NZ voxels in DATA_DIR
# once (benchmarks/geotop_like), imports its lithok as the SBRT
# geotop_NXxNY where the search path lacks it and, with 3D, expands that
# into the 3D raster of the same name (r3.sbrt.convert -r, bit-identical:
# the GRASS route's input); sets map= to the name.
geotop_bench_model() {
    local nx=$1 ny=$2 nz=$3 data=$4 tools=$5 with_3d=${6:-} file gen
    map=geotop_${nx}x${ny}
    gen=$tools/../benchmarks/geotop_like
    make -s -C "$gen" build/geotop_like
    file=$data/geotop_like_${nx}x${ny}x${nz}.nc
    [ -s "$file" ] || { "$gen/build/geotop_like" write "$file.part" "$nx" "$ny" "$nz" &&
                        mv "$file.part" "$file"; }
    local sbrt
    sbrt=$(r3.sbrt.convert -l | sed -n "s/^$map@//p" | head -1)
    sbrt=${sbrt:+$(g.gisenv get=GISDBASE)/$(g.gisenv get=LOCATION_NAME)/$sbrt/sbrt/$map}
    if [ -z "$sbrt" ] || ! bench_sbrt_current "$sbrt" "$tools"; then
        r3.sbrt.convert --q --o -o file="$file" variable=lithok output="$map" >/dev/null || return 1
        bench_sbrt_stamp "$(g.gisenv get=GISDBASE)/$(g.gisenv get=LOCATION_NAME)/$(g.gisenv get=MAPSET)/sbrt/$map" "$tools"
    fi
    if [ -n "$with_3d" ] && [ -z "$(g.list type=raster_3d pattern="$map")" ]; then
        r3.sbrt.convert -s input="$map" >/dev/null || return 1
        r3.sbrt.convert --q -r input="$map" output="$map" >/dev/null
    fi
}
