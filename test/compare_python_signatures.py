"""The two build modes wrap the same Python API: every cv::event signature that OpenCV's generator wrote for the
contrib build's cv2.event equals the standalone build's, and neither has one the other lacks.

    compare_python_signatures.py STANDALONE_JSON CONTRIB_JSON    (pyopencv_signatures.json of each build)
"""
import json
import sys


def event_signatures(path):
    with open(path) as f:
        return {k: v for k, v in json.load(f).items() if k.startswith("cv::event::")}


standalone, contrib = event_signatures(sys.argv[1]), event_signatures(sys.argv[2])
only = sorted(set(standalone) ^ set(contrib))
differ = sorted(k for k in set(standalone) & set(contrib) if standalone[k] != contrib[k])
if only or differ or not standalone:
    sys.exit("python signatures differ between the builds: only in one: %s; different: %s" % (only, differ))
print("python signatures: the %d of cv::event are the same in both builds" % len(standalone))
