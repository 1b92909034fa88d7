#!/usr/bin/env python3
"""Generates the C++ sources of the standalone Python extension with OpenCV's own binding generator.

    generate_bindings.py OPENCV_SOURCE_DIR OPENCV_INCLUDE_DIR OUTPUT_DIR HEADER...

The contrib build wraps every CV_EXPORTS_W / CV_WRAP declaration of the module with OpenCV's gen2.py; this runs
the same generator (from the OpenCV source of the installed version) on the module's public headers, so that
both builds expose the same names with the same behaviour and nothing is wrapped by hand. From the installed
OpenCV it keeps only what the module's API is built on: cv::Algorithm (the base of every algorithm here),
FileStorage and FileNode (Algorithm::write / read) and the UMat declarations that gen2 pairs with every
InputArray; the rest of OpenCV is the distribution's cv2.
"""
import os
import sys

CORE_CLASSES = ("cv.Algorithm", "cv.FileStorage", "cv.FileNode")
CORE_ENUMS = ("enum cv.AccessFlag", "enum cv.UMatUsageFlags")  # UMat's constructors and getMat() take them


def main(argv):
    if len(argv) < 5:
        sys.exit(__doc__)
    source_dir, include_dir, output_dir, headers = argv[1], argv[2], argv[3], argv[4:]
    sys.path.insert(0, os.path.join(source_dir, "modules", "python", "src2"))
    import gen2  # noqa: E402  (OpenCV's generator, from the source tree)
    import hdr_parser  # noqa: E402

    own = set(os.path.abspath(h) for h in headers)
    parse = hdr_parser.CppHeaderParser.parse

    def parse_kept(self, hname, wmode=True):
        decls = parse(self, hname, wmode)
        if os.path.abspath(hname) in own or os.path.basename(hname).startswith("shadow_"):
            return decls
        return [d for d in decls
                if d[0] in CORE_ENUMS or any(d[0] == "class " + c or d[0].startswith(c + ".") for c in CORE_CLASSES)]

    hdr_parser.CppHeaderParser.parse = parse_kept
    core = [os.path.join(include_dir, "opencv2", h) for h in ("core.hpp", "core/mat.hpp", "core/persistence.hpp")]
    shadow = os.path.join(source_dir, "modules", "core", "misc", "python", "shadow_umat.hpp")
    os.makedirs(output_dir, exist_ok=True)
    gen2.PythonWrapperGenerator().gen(core + [shadow] + sorted(headers), output_dir)
    # Converters that gen2's output expects from the wrapped modules' misc/python folders: core's UMat ones.
    custom = os.path.join(source_dir, "modules", "core", "misc", "python", "pyopencv_umat.hpp")
    write_if_changed(os.path.join(output_dir, "pyopencv_custom_headers.h"),
                     '#include "opencv2/core/ocl.hpp"\n#include "%s"\n' % custom)


def write_if_changed(path, text):
    if os.path.exists(path):
        with open(path) as f:
            if f.read() == text:
                return
    with open(path, "w") as f:
        f.write(text)


if __name__ == "__main__":
    main(sys.argv)
