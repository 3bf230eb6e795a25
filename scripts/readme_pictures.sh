#!/usr/bin/env bash
# Regenerates every picture README.md shows, with the same code as the window and the CLI:
# `shadowlab gui --screenshot`, `render`, `bench`, `sweep` and `shimmer`. Run from anywhere after a
# build (scripts/build.sh); it draws under Xvfb when no display is set. Takes under a minute on the
# 2-core machine (the bench and the sweep measure against the exact reference); `--views` redraws
# only the views.
set -euo pipefail
cd "$(dirname "$0")/.."
shadowlab=build/app/shadowlab
images=docs/images
[[ -x $shadowlab ]] || { echo "readme_pictures.sh: build first (scripts/build.sh)" >&2; exit 1; }
x() { if [[ -n ${DISPLAY:-} ]]; then "$@"; else xvfb-run -a -s "-screen 0 1920x1200x24" "$@"; fi; }

# The window at the size the issue judges legibility at.
x $shadowlab gui data/scenes/default.json --size 1280x800 --screenshot $images/window.png

# The views of LiSPSM on the default scene, one per view.
for view in camera world light ppls shadowmap error; do
    x $shadowlab render data/scenes/default.json --method lispsm --view $view --size 800x450 \
        --out $images/view_$view.png
done

# The warp made visible: LiSPSM's light space and PPLS from the side, before and after the warp;
# XPSM's focus region (the paper's Fig. 5) from the light.
x $shadowlab render data/scenes/box_on_plane.json --method lispsm --view light --preset side --step gamma \
    --size 640x400 --out $images/lesson_lispsm_gamma.png
x $shadowlab render data/scenes/box_on_plane.json --method lispsm --view light --preset side --step light-space \
    --size 640x400 --out $images/lesson_lispsm_before_warp.png
x $shadowlab render data/scenes/box_on_plane.json --method lispsm --view ppls --preset side --step warp \
    --size 640x400 --out $images/lesson_lispsm_after_warp.png
x $shadowlab render data/scenes/box_on_plane.json --method xpsm --view light --preset light --step xpsm-4 \
    --size 640x400 --out $images/lesson_xpsm_intervals.png
x $shadowlab render data/scenes/box_on_plane.json --method xpsm --view ppls --preset light --step xpsm-13 \
    --size 640x400 --out $images/lesson_xpsm_focus_region.png

# The interactive lesson in a browser (headless Chromium, WebGL by SwiftShader), at LiSPSM's warp.
lesson=$(mktemp -d)
x $shadowlab lesson data/scenes/box_on_plane.json --method lispsm --interactive --size 480x300 --out "$lesson"
chromium --headless --no-sandbox --use-angle=swiftshader --enable-unsafe-swiftshader --hide-scrollbars \
    --window-size=1500,1100 --virtual-time-budget=5000 --screenshot=$images/lesson_interactive.png \
    "file://$lesson/index.html#warp" 2>/dev/null
rm -rf "$lesson"

# Shadows that read: the teaching scene, and the shadow volumes.
x $shadowlab render data/scenes/teaching.json --method lispsm --view camera --size 800x450 \
    --out $images/teaching_camera.png
x $shadowlab render data/scenes/volumes.json --method volumes --view camera --size 640x360 \
    --out $images/volumes_camera.png
x $shadowlab render data/scenes/volumes_eye_in_shadow.json --method volumes --set count=zpass --view stencil \
    --size 640x360 --out $images/volumes_stencil_zpass.png

# Cascades: the map each pixel reads, the atlas, and the texels where they land.
x $shadowlab render data/scenes/default.json --method cascades --set blend=0.2 --view camera --overlay cascade \
    --size 640x360 --out $images/cascades_overlay.png
x $shadowlab render data/scenes/default.json --method cascades --view shadowmap --size 640x360 \
    --out $images/cascades_atlas.png
x $shadowlab render data/scenes/box_on_plane.json --method cascades --view texels --resolution 128 --size 640x360 \
    --out $images/cascades_texels.png
# Visible depth bounds against the frustum's with logarithmic splits, and a resolution per cascade.
for bounds in frustum visible; do
    x $shadowlab render data/scenes/default.json --method cascades --set lambda=1 --set bounds=$bounds --view camera \
        --overlay cascade --size 640x360 --out $images/cascades_${bounds}_bounds.png
done
x $shadowlab render data/scenes/default.json --method cascades --set tiles=1,0.5,0.5,0.5 --view shadowmap \
    --size 640x360 --out $images/cascades_tiles.png

# Omnidirectional maps in the lamp room: the dual-paraboloid atlas with the bowed edges, its shadows
# without and with the casters split, and the cube's atlas.
x $shadowlab render data/scenes/lamp_room.json --method dpsm --view shadowmap --size 640x360 --out $images/dpsm_atlas.png
x $shadowlab render data/scenes/lamp_room.json --method dpsm --view camera --size 640x360 --out $images/dpsm_camera.png
x $shadowlab render data/scenes/lamp_room.json --method dpsm --set tessellate=0.5 --view camera --size 640x360 \
    --out $images/dpsm_camera_tessellated.png
x $shadowlab render data/scenes/lamp_room.json --method cube --view shadowmap --size 640x360 --out $images/cube_atlas.png

# Tetrahedron maps at 1024²: the four faces' triangles in the texture, the packing step, the face
# serving each surface, and the Camera view without the faces' margin (false shadows along face 3's
# edges) and with it.
tetra="$shadowlab render data/scenes/lamp_room.json --method tetra --resolution 1024 --size 640x360"
x $tetra --view shadowmap --out $images/tetra_atlas.png
x $tetra --view ppls --step tetra-packing --out $images/tetra_packing.png
x $tetra --view camera --overlay cascade --out $images/tetra_faces.png
x $tetra --view camera --set margin=0 --out $images/tetra_camera_margin0.png
x $tetra --view camera --out $images/tetra_camera.png

# Soft shadows: hard, PCF and PCSS under a sun 2° wide; the signed error of PCF and PCSS against the
# soft reference; VSM's blurred moments.
x $shadowlab render data/scenes/box_on_plane.json --method psm --set bias_slope=0.25 --view error --error causes \
    --size 640x360 --out $images/causes_psm_box.png
x $shadowlab render /usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb --method lispsm \
    --view error --error causes --size 640x360 --out $images/causes_lispsm_engine.png

soft() { x $shadowlab render data/scenes/soft_shadows.json --method focused --size 640x360 "$@"; }
soft --set filter=hard --view camera --out $images/soft_hard.png
soft --set filter=pcf --view camera --out $images/soft_pcf.png
soft --set filter=pcss --set kernel_size=4 --view camera --out $images/soft_pcss.png
soft --set filter=pcf --view error --error signed --out $images/error_signed_pcf.png
soft --set filter=pcss --set kernel_size=4 --view error --error signed --out $images/error_signed_pcss.png
soft --set filter=vsm --set kernel_size=5 --view shadowmap --texture deviation --out $images/moments_vsm.png

[[ ${1:-} == --views ]] && exit 0

# The measured trade: error against cost, error as the light turns parallel to the view, and
# LiSPSM's shimmer as the camera moves sideways on the teaching scene.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
x $shadowlab bench data/scenes/default.json --out "$work/bench"
cp "$work/bench/bench.png" "$work/bench/bench_aliasing.png" "$work/bench/bench_storage.png" $images/
x $shadowlab sweep data/scenes/default.json --out "$work/sweep"
cp "$work/sweep/sweep_angle.png" $images/
x $shadowlab bench data/scenes/sun_disc.json --filters --resolutions 2048 --size 640x360 --out "$work/filters"
cp "$work/filters/bench_filters.png" $images/
x $shadowlab sweep data/scenes/grazing_sun.json --bias --methods focused,psm,lispsm,tsm,xpsm,cascades --out "$work/bias"
cp "$work/bias/sweep_bias.png" $images/sweep_bias_grazing.png
x $shadowlab shimmer data/scenes/teaching.json --method lispsm --frames 30 --out "$work/shimmer"
cp "$work/shimmer/shimmer.png" $images/shimmer_lispsm.png
