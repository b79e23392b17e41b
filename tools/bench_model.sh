# Sourced inside a GRASS session by the benchmark scripts:
#   bench_model SIZE TOOLS_DIR
# makes the demo model geo_SIZE where the search path lacks it, converts
# it to an SBRT where none exists, sets map= and sbrt= (the SBRT's
# directory) and the region to the model at 1056 x 884 pixels.
bench_model() {
    local size=$1 tools=$2 loc m
    map=geo_$size
    [ -n "$(g.list type=raster_3d pattern="$map")" ] || "$tools/make_geomodel.sh" "$size" "$map" >/dev/null
    loc=$(g.gisenv get=GISDBASE)/$(g.gisenv get=LOCATION_NAME)
    sbrt=""
    for m in $(g.mapsets -p sep=space); do
        [ -e "$loc/$m/sbrt/$map" ] && { sbrt=$loc/$m/sbrt/$map; break; }
    done
    if [ -z "$sbrt" ]; then
        r3.sbrt.convert --q input="$map" output="$map"
        sbrt=$loc/$(g.gisenv get=MAPSET)/sbrt/$map
    fi
    g.region --q raster_3d="$map"
    g.region --q rows=884 cols=1056
}
