#!/usr/bin/env python3
"""Video helpers for scripts/experiments.sh (needs OpenCV's Python module, cv2).

  exp_frames.py cut VIDEO OUT.avi N          first N frames of VIDEO -> OUT.avi (FFV1, lossless)
  exp_frames.py grab VIDEO OUT.png F1 F2 ... [--width W]
        frames F1, F2, ... side by side in one PNG, each scaled to width W (default 240)

Exit code 3 when cv2 is missing, so the caller can skip the step with a message.
"""
import sys

try:
    import cv2
except ImportError:
    sys.stderr.write("exp_frames.py: python module cv2 (OpenCV) not found\n")
    sys.exit(3)


def cut(video, out, n):
    cap = cv2.VideoCapture(video)
    if not cap.isOpened():
        sys.exit(f"{video}: cannot open")
    fps = cap.get(cv2.CAP_PROP_FPS) or 25.0
    w, h = int(cap.get(cv2.CAP_PROP_FRAME_WIDTH)), int(cap.get(cv2.CAP_PROP_FRAME_HEIGHT))
    writer = cv2.VideoWriter(out, cv2.VideoWriter_fourcc(*"FFV1"), fps, (w, h))
    count = 0
    while count < n:
        ok, frame = cap.read()
        if not ok:
            break
        writer.write(frame)
        count += 1
    writer.release()
    print(f"{out}: {count} frames {w}x{h} at {fps:g} fps")


def grab(video, out, frames, width):
    cap = cv2.VideoCapture(video)
    if not cap.isOpened():
        sys.exit(f"{video}: cannot open")
    tiles = []
    wanted = sorted(set(frames))
    index = 0
    while wanted:
        ok, frame = cap.read()
        if not ok:
            break
        if index == wanted[0]:
            scale = width / frame.shape[1]
            tile = cv2.resize(frame, (width, int(round(frame.shape[0] * scale))), interpolation=cv2.INTER_AREA)
            cv2.putText(tile, f"frame {index}", (4, 16), cv2.FONT_HERSHEY_SIMPLEX, 0.45, (255, 255, 255), 1)
            tiles.append(tile)
            wanted.pop(0)
        index += 1
    if not tiles:
        sys.exit(f"{video}: none of the frames {frames} exist")
    cv2.imwrite(out, cv2.hconcat(tiles), [cv2.IMWRITE_PNG_COMPRESSION, 9])
    print(f"{out}: frames {[f for f in frames if f < index]}")


def main():
    if len(sys.argv) < 2 or sys.argv[1] not in ("cut", "grab"):
        sys.exit(__doc__)
    if sys.argv[1] == "cut":
        cut(sys.argv[2], sys.argv[3], int(sys.argv[4]))
    else:
        args = sys.argv[4:]
        width = 240
        if "--width" in args:
            i = args.index("--width")
            width = int(args[i + 1])
            del args[i:i + 2]
        grab(sys.argv[2], sys.argv[3], [int(a) for a in args], width)


if __name__ == "__main__":
    main()
