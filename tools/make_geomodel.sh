#!/usr/bin/env bash
############################################################################
# MODULE:    tools/make_geomodel.sh (r3.sbrt addon)
# PURPOSE:   Built-in synthetic geological model as a categorical 3D raster
#            (r3.mapcalc), at any size, with labels and colours per class.
#            Same geology as ../shared/peers/make_data.sh, so our figures and
#            the peers' are taken on identical data.
# USAGE:     (inside a GRASS session) make_geomodel.sh SIZE [NAME]
#            SIZE: T (40x50x64), S (100x125x80), A (200x250x320),
#                  B (400x500x400), C (800x1000x800) or COLSxROWSxDEPTHS
#            Sets the 2D and 3D region to the model. NAME default geo_SIZE.
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
# The extent is fixed (2000 m E-W x 2500 m N-S x 640 m), only the resolution
# changes. Classes: 1..13 folded strata (a fault, a dome, an escarpment),
# 14 gravel aquifer lens, 15 clay lens, 16 basalt dike; null above the
# terrain (air) and in a cave under the escarpment's overhang.
set -euo pipefail
size=${1:?usage: make_geomodel.sh SIZE [NAME]}
case $size in
    T) dims=40x50x64 ;;
    S) dims=100x125x80 ;;
    A) dims=200x250x320 ;;
    B) dims=400x500x400 ;;
    C) dims=800x1000x800 ;;
    *x*x*) dims=$size ;;
    *) echo "make_geomodel.sh: unknown size '$size' (T S A B C or CxRxD)" >&2; exit 2 ;;
esac
name=${2:-geo_$size}
IFS=x read -r cols rows depths <<<"$dims"
res() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.17g", a / b }'; }
# g.region 8.2 has a single res3= for both horizontal 3D resolutions
if [ "$(res 2500 "$rows")" != "$(res 2000 "$cols")" ]; then
    echo "make_geomodel.sh: cols:rows must be 4:5 (square cells), got $dims" >&2
    exit 2
fi
g.region n=2500 s=0 w=0 e=2000 b=0 t=640 res="$(res 2000 "$cols")" \
    res3="$(res 2000 "$cols")" tbres="$(res 640 "$depths")" >/dev/null

expr='eval(u = x()/2000.0, v = y()/2500.0, w = z(),
 us = 0.5 + 0.06*sin(540*v),
 hills = 18*sin(360*(1.2*u+0.1))*cos(288*v) + 8*sin(360*(3.1*u+2.3*v)),
 top = 545 + 40*atan(150*(us - u))/90 + hills,
 fold = 40*sin(360*(1.6*u + 0.35*v)) + 20*cos(360*(1.1*v - 0.2*u))*sin(324*u) - 60*u
        + 110*exp(-((u-0.78)^2 + (v-0.62)^2)/0.03),
 uf = 0.74 + 0.08*v - 0.12*w/640,
 ze = w + 40*(u > uf),
 strat = 1 + (ze > 45+1.00*fold) + (ze > 95+0.98*fold) + (ze > 145+0.96*fold) + (ze > 195+0.94*fold)
           + (ze > 240+0.92*fold) + (ze > 285+0.90*fold) + (ze > 330+0.88*fold) + (ze > 375+0.86*fold)
           + (ze > 420+0.84*fold) + (ze > 460+0.82*fold) + (ze > 500+0.80*fold) + (ze > 540+0.78*fold),
 lens14 = ((u-0.30)/0.13)^2 + ((v-0.62)/0.10)^2 + ((ze-(352+0.87*fold))/13)^2 < 1,
 lens15 = ((u-0.80)/0.08)^2 + ((v-0.30)/0.12)^2 + ((ze-(217+0.93*fold))/9)^2 < 1,
 dike16 = abs((u - 0.20) - 0.25*(v - 0.5) + 0.00015*(w - 300)) < 0.004 && w < 470,
 zc = 505 + 18*sin(360*(1.2*us+0.1))*cos(288*v) + 8*sin(360*(3.1*us+2.3*v)) + 12,
 cave = ((u - (us - 0.01))/0.025)^2 + ((v - 0.45)/0.06)^2 + ((w - zc)/10)^2 < 1,
 if(w > top || cave, null(), float(if(dike16, 16, if(lens14, 14, if(lens15, 15, strat))))))'
r3.mapcalc --overwrite --quiet expression="$name = ${expr//$'\n'/ }"

r3.colors --quiet map="$name" rules=- <<'COLORS'
1 70:50:40
2 120:90:60
3 160:120:80
4 200:170:110
5 110:140:90
6 80:120:160
7 170:80:70
8 230:210:140
9 140:160:120
10 190:140:190
11 100:100:100
12 220:140:60
13 150:200:90
14 30:110:230
15 200:40:40
16 20:20:20
COLORS

# category labels: 8.2's r3.support raster= cannot copy them (docs/BUILD-NOTES.md
# 8), so the 3D raster's cats file is written in GRASS's own cats format
mapset=$(g.gisenv get=MAPSET)
dir="$(g.gisenv get=GISDBASE)/$(g.gisenv get=LOCATION_NAME)/$mapset/grid3/$name"
cat >"$dir/cats" <<'CATS'
# 16 categories
Synthetic geology

0.00 0.00 0.00 0.00
1:Basement gneiss
2:Lower sandstone
3:Red siltstone
4:Quartz arenite
5:Grey shale
6:Blue limestone
7:Marl
8:Upper sandstone
9:Dolomite
10:Mudstone
11:Chert
12:Conglomerate
13:Topsoil and till
14:Gravel aquifer
15:Clay lens
16:Basalt dike
CATS
echo "make_geomodel: $name ${cols}x${rows}x${depths}"
