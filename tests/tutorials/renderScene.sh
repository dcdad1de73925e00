#!/bin/bash
#------------------------------------------------------------------------------
# Test of tutorials/bin/renderScene: renders three short runs and checks the
# pictures against the scene projected here, independently, through the
# camera that renderScene reports (position, focal point, view up, view angle
# or parallel scale):
#  - mooredFloatingObject (3D, the cube moored by four catenary lines) to
#    0.1 s; its lines written as the bridge's VTK connector files
#    (VTK/fmuConnectors/<line>_<i>.vtk and <line>.vtk.series; made here
#    from the lines' shape outputs in postProcessing/fmuConnectors/0/<line>.dat
#    when the bridge does not write them):
#    the picture has the size asked for (-size); the water colour covers the
#    projected free surface (the plane z = 0.5 m across the tank) and little
#    else; the body colour lies within the cube's projection and fills a
#    good part of it; the picture without the body (-bodies none) differs
#    only there, without the lines (-lines none) only along their projected
#    shapes; from the .dat files alone (no VTK folder) the picture is the
#    same;
#  - mooredFloatingBodyOverset (2D, overset) to 0.1 s, side view: the water
#    fills the projected rectangle below the still-water level, not above;
#    the body colour fills the cube's projected square (at its logged
#    centre), and the picture without the body differs only there; an
#    animation has a frame per written time, encoded to a GIF when ffmpeg
#    or ImageMagick is there;
#  - hingedFloatingObjects with a spring and a damper to anchors in the
#    fixed world added (3D, 0.1 s): the summary counts the spring, the
#    damper and the hinge; each drawn alone differs from the picture
#    without them only along the segment between its attachment points
#    (placed independently from the bodies' logged motion, checked against
#    the connector's length output; the hinge along its axis at the joint),
#    with enough pixels, and in its colour; without the table of the
#    bodies' motion the connectors are placed by the state written at the
#    time, in the same picture;
#  - a time that was not written is an error naming -time.
# Needs ParaView (pvbatch, pvpython; Debian packages paraview,
# python3-paraview), xvfb-run without a display (xvfb), ffmpeg or ImageMagick
# for the GIF, and what the three tutorials need (./Allwmake).
# Exits non-zero on the first failure.
#------------------------------------------------------------------------------
. "$(dirname "$0")/tutorialTestFunctions"

render="$FOAMFMI_DIR/tutorials/bin/renderScene"
endTime=0.1

command -v pvbatch > /dev/null 2>&1 \
    || fail "pvbatch not found (Debian packages paraview, python3-paraview)"
requireFile "$FOAM_USER_LIBBIN/libfoamFmiBridge.so" \
    "the bridge library (build it: ./Allwmake)"
for fmu in catenary hinge linearSpring linearDamper
do
    requireFile "$FOAMFMI_FMU_DIR/$fmu.fmu" "the $fmu FMU (build it: ./Allwmake)"
done

makeWorkDir
checker="$(cd "$(dirname "$0")" && pwd -P)/checkPicture.py"

# renderTo CASE PNG [OPTIONS]: render, keep the camera line in PNG.camera
renderTo()
{
    local caseDir="$1" png="$2"
    shift 2
    "$render" -output "$png" "$@" "$caseDir" > "$png.log" 2>&1 \
        || { cat "$png.log" 1>&2; fail "renderScene $* $caseDir failed"; }
    grep '^camera:' "$png.log" > "$png.camera" \
        || { cat "$png.log" 1>&2; fail "renderScene printed no camera"; }
}

# check ARGS: the picture checks of checkPicture.py, run by ParaView's Python
# (numpy, VTK)
check()
{
    pvpython "$checker" -- "$@" 2>&1 | grep -v '^\s*$' > "$workDir/check.log"
    local status=${PIPESTATUS[0]}
    sed -n 's/^ok: /ok   ['"$testName"']: /p' "$workDir/check.log"
    [ "$status" -eq 0 ] || { grep -v '^ok: ' "$workDir/check.log" 1>&2; fail "$1 ($*)"; }
}

# 3D: the moored cube, its lines as VTK connector files
moored=$workDir/mooredFloatingObject
runTutorial mooredFloatingObject "$moored" -mesh-factor 0.5 -end-time $endTime -no-plot
[ -d "$moored/$endTime" ] || fail "no time $endTime written in $moored"
check make_vtk "$moored"
renderTo "$moored" "$workDir/moored.png" -time $endTime -size 960x540
grep -q "lines: 4 of 4; springs: 0 of 0; dampers: 0 of 0; hinges: 0 of 0)" \
    "$workDir/moored.png.log" \
    || fail "not the four lines alone drawn: $(head -n 1 "$workDir/moored.png.log")"
renderTo "$moored" "$workDir/mooredNoBody.png" -time $endTime -size 960x540 -bodies none
renderTo "$moored" "$workDir/mooredNoLines.png" -time $endTime -size 960x540 -lines none
mv "$moored/VTK" "$moored/VTK.off"
renderTo "$moored" "$workDir/mooredFromDat.png" -time $endTime -size 960x540
mv "$moored/VTK.off" "$moored/VTK"
check 3d "$workDir/moored.png" "$workDir/mooredNoBody.png" \
    "$workDir/mooredNoLines.png" "$workDir/mooredFromDat.png" "$moored" \
    $endTime 960 540

# A time that was not written
if "$render" -time 0.05 "$moored" > "$workDir/badTime.log" 2>&1
then
    fail "renderScene -time 0.05 (not written) succeeded"
fi
grep -q -- "-time 0.05: not a written time" "$workDir/badTime.log" \
    || { cat "$workDir/badTime.log" 1>&2; fail "no error naming -time"; }
pass "-time 0.05 (not written): $(grep -- '-time' "$workDir/badTime.log")"

# 3D: a spring, a damper and a hinge: hingedFloatingObjects (its hinge
# between the cubes) with a spring and a damper from the cubes' outer faces
# to anchors in the fixed world
conn=$workDir/connectors
cp -r "$FOAMFMI_DIR/tutorials/hingedFloatingObjects" "$conn" \
    || fail "cannot copy hingedFloatingObjects"
"$conn/Allclean" > /dev/null 2>&1 || fail "hingedFloatingObjects: Allclean failed"
check add_connectors "$conn"
echo "Running hingedFloatingObjects with a spring and a damper in $conn"
"$conn/Allrun" -end-time $endTime -no-plot > "$conn/log.Allrun" 2>&1 \
    || { tail -n 25 "$conn/log.Allrun" 1>&2; fail "Allrun failed (see $conn/log.Allrun)"; }
renderTo "$conn" "$workDir/conn.png" -time $endTime -size 960x540
grep -q "springs: 1 of 1; dampers: 1 of 1; hinges: 1 of 1)" "$workDir/conn.png.log" \
    || fail "not the spring, the damper and the hinge drawn: $(head -n 1 "$workDir/conn.png.log")"
pass "$(head -n 1 "$workDir/conn.png.log")"
renderTo "$conn" "$workDir/connNone.png" -time $endTime -size 960x540 -connectors none
for name in spring damper hinge
do
    renderTo "$conn" "$workDir/conn_$name.png" -time $endTime -size 960x540 -connectors $name
done
check connectors "$workDir/conn.png" "$workDir/connNone.png" "$conn" $endTime
# Without the table of the bodies' motion (postProcessing/rigidBodyMotion,
# which Allrun makes from the log) the connectors are placed by the state
# OpenFOAM wrote at the time (the joints' q): the same picture. The table
# holds the log's 6 digits, the state 17, so an edge pixel may turn: at most
# 20 of the 518400 (measured: 0)
mv "$conn/postProcessing/rigidBodyMotion" "$conn/postProcessing/rigidBodyMotion.off"
renderTo "$conn" "$workDir/connState.png" -time $endTime -size 960x540
mv "$conn/postProcessing/rigidBodyMotion.off" "$conn/postProcessing/rigidBodyMotion"
grep -q "springs: 1 of 1; dampers: 1 of 1; hinges: 1 of 1)" "$workDir/connState.png.log" \
    || fail "from the written state: not the spring, the damper and the hinge drawn:" \
        "$(head -n 1 "$workDir/connState.png.log")"
! grep -q "no motion of" "$workDir/connState.png.log" \
    || fail "from the written state: $(grep "no motion of" "$workDir/connState.png.log")"
check same "$workDir/conn.png" "$workDir/connState.png" \
    "the connectors placed by the written state, not the motion's table" 20

# 2D: the overset cube, side view, default picture and animation
overset=$workDir/mooredFloatingBodyOverset
runTutorial mooredFloatingBodyOverset "$overset" -end-time $endTime -no-plot
renderTo "$overset" "$workDir/overset.png"
renderTo "$overset" "$workDir/oversetNoBody.png" -bodies none
check 2d "$workDir/overset.png" "$workDir/oversetNoBody.png" "$overset" $endTime

"$render" -animation "$overset" > "$workDir/animation.log" 2>&1 \
    || { cat "$workDir/animation.log" 1>&2; fail "renderScene -animation failed"; }
nFrames=$(ls "$overset" | grep -c -E '^[0-9.]+(e[-+]?[0-9]+)?$')
if command -v ffmpeg > /dev/null 2>&1 || command -v convert > /dev/null 2>&1
then
    gif="$overset/plots/scene.gif"
    [ "$(head -c 4 "$gif" 2>/dev/null)" = "GIF8" ] \
        || { cat "$workDir/animation.log" 1>&2; fail "no GIF written: $gif"; }
    grep -q "($nFrames frames," "$workDir/animation.log" \
        || { cat "$workDir/animation.log" 1>&2; fail "not $nFrames frames"; }
    pass "$(grep '^renderScene: wrote' "$workDir/animation.log")"
else
    [ "$(ls "$overset"/plots/scene_frames/frame_*.png | wc -l)" -eq "$nFrames" ] \
        || fail "not $nFrames frames in $overset/plots/scene_frames"
    pass "$nFrames frames (no encoder)"
fi

echo "renderScene: all checks passed"
