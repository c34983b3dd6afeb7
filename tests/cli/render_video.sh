#!/bin/sh
# `render --sequence` writes the output of every frame, numbered, and the frames move with time;
# `render --video` encodes them with ffmpeg (when installed: frame count and rate checked with
# ffprobe; when not: exit 3 naming the setup script), never overwrites a file and leaves no
# scratch folder behind; an unknown container is a usage error.
# Usage: render_video.sh PASSLAB WORKDIR
set -eu
passlab=$1 work=$2
rm -rf "$work"; mkdir -p "$work"
fail() { echo "FAIL: $1" >&2; exit 1; }

"$passlab" render procedural/fbm -o "$work/seq" --frames 4 --step 0.25 --time 1 --size 96x54 --sequence > "$work/seq.txt" 2> "$work/seq.err" || fail "--sequence: $(cat "$work/seq.err")"
for i in 00000 00001 00002 00003; do
  [ -f "$work/seq/fbm.$i.png" ] || fail "--sequence did not write fbm.$i.png"
  grep -q "fbm.$i.png" "$work/seq.txt" || fail "fbm.$i.png is not printed"
done
[ ! -e "$work/seq/fbm.00004.png" ] || fail "--sequence wrote a fifth frame"
! cmp -s "$work/seq/fbm.00000.png" "$work/seq/fbm.00003.png" || fail "the frames do not move with time"
cmp -s "$work/seq/fbm.00003.png" "$work/seq/fbm.png" || fail "the last frame differs from the output image"

rc=0; "$passlab" render procedural/fbm -o "$work/v" --video "$work/v/clip.avi" > /dev/null 2> "$work/avi.err" || rc=$?
[ "$rc" = 2 ] && grep -q "must end in .mp4" "$work/avi.err" || fail "--video .avi: exit $rc: $(cat "$work/avi.err")"
mkdir -p "$work/v"; echo keep > "$work/v/taken.mp4"
rc=0; "$passlab" render procedural/fbm -o "$work/v" --video "$work/v/taken.mp4" > /dev/null 2> "$work/taken.err" || rc=$?
[ "$rc" = 2 ] && grep -q "never overwrites" "$work/taken.err" || fail "--video over a file: exit $rc"
[ "$(cat "$work/v/taken.mp4")" = keep ] || fail "--video overwrote a file"

before=$(ls "${TMPDIR:-/tmp}" | grep -c '^passlab-video-' || true)
if command -v ffmpeg > /dev/null 2>&1 && command -v ffprobe > /dev/null 2>&1; then
  "$passlab" render procedural/fbm -o "$work/v" --frames 12 --step 0.1 --time 1.1 --size 97x55 --video "$work/v/clip.mp4" > "$work/v.txt" 2> "$work/v.err" || fail "--video mp4: $(cat "$work/v.err")"
  grep -q "clip.mp4" "$work/v.txt" || fail "the video path is not printed"
  info=$(ffprobe -v error -select_streams v:0 -count_frames -show_entries stream=nb_read_frames,r_frame_rate,width,height -of csv=p=0 "$work/v/clip.mp4")
  [ "$info" = "98,56,10/1,12" ] || fail "mp4: expected 98x56 (padded to even), 10 fps, 12 frames; ffprobe says $info"
  "$passlab" render procedural/fbm -o "$work/v" --frames 5 --size 64x36 --video "$work/v/clip.gif" > /dev/null 2> "$work/g.err" || fail "--video gif: $(cat "$work/g.err")"
  n=$(ffprobe -v error -count_frames -show_entries stream=nb_read_frames -of csv=p=0 "$work/v/clip.gif")
  [ "$n" = 5 ] || fail "gif: expected 5 frames, ffprobe says $n"
  echo "ffmpeg present: mp4 and gif encoded"
else
  rc=0; "$passlab" render procedural/fbm -o "$work/v" --video "$work/v/clip.mp4" > /dev/null 2> "$work/none.err" || rc=$?
  [ "$rc" = 3 ] && grep -q "deps.sh --video" "$work/none.err" || fail "--video without ffmpeg: exit $rc: $(cat "$work/none.err")"
  [ ! -e "$work/v/clip.mp4" ] || fail "a video file was written without ffmpeg"
  echo "ffmpeg absent: --video refused with exit 3"
fi
after=$(ls "${TMPDIR:-/tmp}" | grep -c '^passlab-video-' || true)
[ "$before" = "$after" ] || fail "a passlab-video-* scratch folder was left behind"
echo "render --sequence/--video: passed"
