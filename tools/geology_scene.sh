# Sourced by tools/demo.sh and benchmarks/geology_views_benchmark.sh
# (inside GRASS, after make_geomodel.sh made the model): the inputs of the
# geological views on the synthetic model, and the views themselves.
#   make_geology_inputs       wells (points with logs), fence lines, ortho
#   GEOLOGY_VIEWS             name|options of each view (paper's Figure 12
#                             plus a fence diagram and the boreholes alone)
make_geology_inputs() {
    # twelve wells on a jittered grid, each with a driller's log of three
    # intervals (depths below the terrain) in a table linked by cat
    awk 'BEGIN { srand(7); n = 0
        for (i = 0; i < 4; i++) for (j = 0; j < 3; j++)
            printf "%d|%.1f|%.1f\n", ++n, 250 + 500 * j + 120 * (rand() - 0.5),
                   250 + 620 * i + 120 * (rand() - 0.5) }' >"$TMPDIR_SCENE/wells.txt"
    v.in.ascii --q --o input="$TMPDIR_SCENE/wells.txt" output=wells separator=pipe \
        columns="cat int, x double precision, y double precision" x=2 y=3 cat=1
    db.execute sql="DROP TABLE IF EXISTS wells_log"
    db.execute sql="CREATE TABLE wells_log (cat integer, depth_top double precision, depth_bottom double precision, lith integer)"
    for n in $(seq 1 12); do
        db.execute sql="INSERT INTO wells_log VALUES ($n, 0, $((20 + 3 * n)), 13)"
        db.execute sql="INSERT INTO wells_log VALUES ($n, $((20 + 3 * n)), $((90 + 5 * n)), 12)"
        db.execute sql="INSERT INTO wells_log VALUES ($n, $((90 + 5 * n)), 400, 11)"
    done
    v.db.connect --q --o map=wells table=wells_log layer=1 key=cat 2>/dev/null
    # a fence diagram: a zig-zag across the anticline and a line along it
    v.in.ascii --q --o -n format=standard input=- output=fence_lines <<'FENCE'
L 4
 150 300
 800 1100
 1250 900
 1900 1800
L 2
 300 2250
 1750 2250
FENCE
    # an "orthophoto": fields and woods (r.mapcalc's sin() takes degrees)
    # crossed by a winding road, on the model's grid
    g.region --q raster_3d=geology
    r.mapcalc --q --o expression="ortho = if(abs(y() - 1300 - 200 * sin(x() * 0.2)) < 12, 250, int(110 + 45 * sin(x() * 0.9) * cos(y() * 0.7) + 30 * sin((x() + y()) * 2.3) + 15 * sin(x() * 7.1) * sin(y() * 5.3)))"
    r.colors --q map=ortho rules=- <<'COLORS'
40 35:65:30
90 70:110:45
130 150:160:80
170 205:190:130
200 225:215:170
250 180:170:160
COLORS
}

HIDDEN_STRATA=13,12,11,10,9
GEOLOGY_VIEWS=(
    "view|"
    "hidden|hide=$HIDDEN_STRATA"
    "drape|texture=ortho texture_blend=0.85"
    "boreholes|boreholes=wells borehole_radius=22 hide=$HIDDEN_STRATA"
    "section|section=0,1200,2000,1500"
    "fence|fence=fence_lines"
    "logs|boreholes=wells borehole_radius=22 -b -m log_top=depth_top log_bottom=depth_bottom log_class=lith log_reference=depth"
)
