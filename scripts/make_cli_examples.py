#!/usr/bin/python3
# Makes the small examples the command-line programs' tests read (data/sequences/, data/matches/)
# from the project's rendered rail-a sequences (Blender renders made for this project, see
# data/rail/README.md):
#   data/sequences/tum/    frames 0, 10, 20 of rail-a `optic` (forward motion) in the TUM RGB-D
#                          layout: rgb/<timestamp>.png, rgb.txt, groundtruth.txt (all 61 poses,
#                          `timestamp tx ty tz qx qy qz qw`, camera-to-world), camera.txt
#   data/sequences/kitti/  frames 0, 10, 20 of rail-a `horizontal` (sideways motion) named as KITTI
#                          odometry names them (000000.png, ...), poses.txt (frames 0..20, 12
#                          numbers per line, 3 x 4 camera-to-world), camera.txt
#   data/matches/          matches of rail-a horizontal frames 0 and 10 found by another front end
#                          (OpenCV's ORB, 2000 features, cross-checked brute-force matching), as
#                          CSV (x1,y1,x2,y2), YAML and JSON (OpenCV FileStorage, points1/points2)
# The frames are stored grey and at half size (320 x 240, INTER_AREA; the camera matrix halved
# with pixel centres kept: c' = (c + 0.5) / 2 - 0.5) so that each example stays under 200 KB.
# Timestamps of the TUM example are synthetic (10 frames per second from 1700000000 s).
#
# usage: /usr/bin/python3 scripts/make_cli_examples.py [--rail-a /work/shared/data/rail-a]
# Licensed under the Apache License, Version 2.0.
import argparse
import os

import cv2
import numpy as np

FRAMES = [0, 10, 20]
T0, DT = 1700000000.0, 0.1


def read_rail(sequence_dir):
    K = np.loadtxt(os.path.join(sequence_dir, "camera.txt"))
    poses = {}
    for row in np.loadtxt(os.path.join(sequence_dir, "poses.txt")):
        poses[int(row[0])] = (row[1:10].reshape(3, 3), row[10:13])  # R world-to-camera, C
    return K, poses


def half_size(image):
    return cv2.resize(image, (image.shape[1] // 2, image.shape[0] // 2),
                      interpolation=cv2.INTER_AREA)


def half_camera(K):
    H = K.copy()
    H[0, 0] /= 2
    H[1, 1] /= 2
    H[0, 2] = (K[0, 2] + 0.5) / 2 - 0.5
    H[1, 2] = (K[1, 2] + 0.5) / 2 - 0.5
    return H


def write_camera(path, K):
    np.savetxt(path, K, fmt="%.12f")


def grey_frame(sequence_dir, k):
    image = cv2.imread(os.path.join(sequence_dir, "%03d.jpg" % k), cv2.IMREAD_GRAYSCALE)
    if image is None:
        raise SystemExit("cannot read frame %d of %s" % (k, sequence_dir))
    return half_size(image)


def quaternion(R):
    """Unit quaternion (x, y, z, w) of the rotation R, w >= 0."""
    w = np.sqrt(max(0.0, 1.0 + np.trace(R))) / 2
    x = np.copysign(np.sqrt(max(0.0, 1 + R[0, 0] - R[1, 1] - R[2, 2])) / 2, R[2, 1] - R[1, 2])
    y = np.copysign(np.sqrt(max(0.0, 1 - R[0, 0] + R[1, 1] - R[2, 2])) / 2, R[0, 2] - R[2, 0])
    z = np.copysign(np.sqrt(max(0.0, 1 - R[0, 0] - R[1, 1] + R[2, 2])) / 2, R[1, 0] - R[0, 1])
    q = np.array([x, y, z, w])
    return q / np.linalg.norm(q)


def make_tum(rail, out):
    sequence = os.path.join(rail, "optic")
    K, poses = read_rail(sequence)
    os.makedirs(os.path.join(out, "rgb"), exist_ok=True)
    with open(os.path.join(out, "rgb.txt"), "w") as listing:
        listing.write("# grey frames 0, 10, 20 of rail-a optic at half size\n"
                      "# timestamp filename\n")
        for k in FRAMES:
            stamp = "%.6f" % (T0 + DT * k)
            name = "rgb/%s.png" % stamp
            cv2.imwrite(os.path.join(out, name), grey_frame(sequence, k),
                        [cv2.IMWRITE_PNG_COMPRESSION, 9])
            listing.write("%s %s\n" % (stamp, name))
    with open(os.path.join(out, "groundtruth.txt"), "w") as truth:
        truth.write("# ground truth of rail-a optic, camera-to-world\n"
                    "# timestamp tx ty tz qx qy qz qw\n")
        for k in sorted(poses):
            R, C = poses[k]
            q = quaternion(R.T)
            truth.write("%.6f %.6f %.6f %.6f %.9f %.9f %.9f %.9f\n"
                        % (T0 + DT * k, C[0], C[1], C[2], q[0], q[1], q[2], q[3]))
    write_camera(os.path.join(out, "camera.txt"), half_camera(K))


def make_kitti(rail, out):
    sequence = os.path.join(rail, "horizontal")
    K, poses = read_rail(sequence)
    os.makedirs(out, exist_ok=True)
    for k in FRAMES:
        cv2.imwrite(os.path.join(out, "%06d.png" % k), grey_frame(sequence, k),
                    [cv2.IMWRITE_PNG_COMPRESSION, 9])
    with open(os.path.join(out, "poses.txt"), "w") as truth:
        for k in range(max(FRAMES) + 1):  # line i is frame i
            R, C = poses[k]
            P = np.hstack([R.T, C.reshape(3, 1)])
            truth.write(" ".join("%.9e" % v for v in P.reshape(-1)) + "\n")
    write_camera(os.path.join(out, "camera.txt"), half_camera(K))


def make_matches(rail, out):
    sequence = os.path.join(rail, "horizontal")
    image1 = cv2.imread(os.path.join(sequence, "000.jpg"), cv2.IMREAD_GRAYSCALE)
    image2 = cv2.imread(os.path.join(sequence, "010.jpg"), cv2.IMREAD_GRAYSCALE)
    orb = cv2.ORB_create(2000)
    k1, d1 = orb.detectAndCompute(image1, None)
    k2, d2 = orb.detectAndCompute(image2, None)
    matches = cv2.BFMatcher(cv2.NORM_HAMMING, crossCheck=True).match(d1, d2)
    p1 = np.float32([k1[m.queryIdx].pt for m in matches])
    p2 = np.float32([k2[m.trainIdx].pt for m in matches])
    os.makedirs(out, exist_ok=True)
    base = os.path.join(out, "rail_000_010")
    with open(base + ".csv", "w") as csv:
        csv.write("# ORB (2000 features) + cross-checked matching, rail-a horizontal 0 -> 10\n")
        csv.write("x1,y1,x2,y2\n")
        for a, b in zip(p1, p2):
            csv.write("%.2f,%.2f,%.2f,%.2f\n" % (a[0], a[1], b[0], b[1]))
    for ext in (".yml", ".json"):
        fs = cv2.FileStorage(base + ext, cv2.FILE_STORAGE_WRITE)
        fs.write("points1", p1)
        fs.write("points2", p2)
        fs.release()
    return len(matches)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--rail-a", default="/work/shared/data/rail-a")
    args = parser.parse_args()
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data")
    make_tum(args.rail_a, os.path.join(root, "sequences", "tum"))
    make_kitti(args.rail_a, os.path.join(root, "sequences", "kitti"))
    n = make_matches(args.rail_a, os.path.join(root, "matches"))
    print("wrote data/sequences/tum, data/sequences/kitti, data/matches (%d matches)" % n)


if __name__ == "__main__":
    main()
