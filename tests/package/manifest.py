#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""What a packaging manifest builds, for tests/suite_package.sh.

    manifest.py platformio DIR   DIR/library.json
    manifest.py arduino DIR      DIR/library.properties
    manifest.py kconfig FILE     the defaults of a Kconfig file

For the first two, prints one "KIND value" a line: SRC (a source file),
INC (an include folder), DEF (a definition), OPT (another compiler flag),
VERSION; each follows its build system's rules for a library: PlatformIO
compiles what srcFilter picks under srcDir (default src, filter
"+<*> -<.git/> -<.svn/>") and puts srcDir and includeDir on the include
path, with build.flags; Arduino (library format 1.5) compiles everything
under src/ with src/ on the include path, and takes no flags. It exits
non-zero, saying why, when a field either requires is missing. kconfig
prints -DCONFIG_NAME=VALUE for every symbol's default (a bool that
defaults to n is left out, as Kconfig leaves it undefined).
"""
import fnmatch
import json
import os
import re
import shlex
import sys

SOURCES = (".c", ".cpp", ".cc", ".cxx", ".S", ".s")


def walk(top):
    for base, dirs, files in os.walk(top):
        dirs.sort()
        for f in sorted(files):
            yield os.path.relpath(os.path.join(base, f), top)


def platformio(d):
    with open(os.path.join(d, "library.json")) as f:
        m = json.load(f)
    for key in ("name", "version"):
        if key not in m:
            sys.exit("library.json: no %r" % key)
    build = m.get("build", {})
    src = os.path.join(d, build.get("srcDir", "src"))
    flt = build.get("srcFilter", "+<*> -<.git/> -<.svn/>")
    if isinstance(flt, list):
        flt = " ".join(flt)
    rules = re.findall(r"([+-])<([^>]*)>", flt)
    picked = []
    for rel in walk(src):
        keep = False
        for sign, pat in rules:
            d_pat = pat.rstrip("/")
            if fnmatch.fnmatch(rel, pat) or rel.startswith(d_pat + "/"):
                keep = sign == "+"
        if keep and rel.endswith(SOURCES):
            picked.append(os.path.join(src, rel))
    print("VERSION %s" % m["version"])
    for p in picked:
        print("SRC %s" % p)
    print("INC %s" % src)
    inc = os.path.join(d, build.get("includeDir", "include"))
    if os.path.isdir(inc) and inc != src:
        print("INC %s" % inc)
    flags = build.get("flags", [])
    if isinstance(flags, str):
        flags = [flags]
    words = shlex.split(" ".join(flags))
    i = 0
    while i < len(words):
        w = words[i]
        if w in ("-I", "-D") and i + 1 < len(words):
            i += 1
            w += words[i]
        if w.startswith("-I"):
            print("INC %s" % os.path.join(d, w[2:]))
        elif w.startswith("-D"):
            print("DEF %s" % w[2:])
        else:
            print("OPT %s" % w)
        i += 1


def arduino(d):
    props = {}
    with open(os.path.join(d, "library.properties")) as f:
        for line in f:
            line = line.strip()
            if line and not line.startswith("#") and "=" in line:
                k, v = line.split("=", 1)
                props[k.strip()] = v.strip()
    for key in ("name", "version", "author", "maintainer", "sentence",
                "paragraph", "category", "architectures"):
        if not props.get(key):
            sys.exit("library.properties: no %r" % key)
    src = os.path.join(d, "src")
    if not os.path.isdir(src):
        sys.exit("library.properties: no src/ beside it (library format 1.5)")
    print("VERSION %s" % props["version"])
    for rel in walk(src):
        if rel.endswith(SOURCES):
            print("SRC %s" % os.path.join(src, rel))
    print("INC %s" % src)
    for h in props.get("includes", "").split(","):
        if h.strip() and not os.path.isfile(os.path.join(src, h.strip())):
            sys.exit("library.properties: includes=%s is not in src/" % h)


def kconfig(path):
    name, kind = None, None
    with open(path) as f:
        for line in f:
            w = line.split()
            if not w:
                continue
            if w[0] in ("config", "menuconfig"):
                name, kind = w[1], None
            elif w[0] in ("bool", "int", "hex", "string"):
                kind = w[0]
            elif w[0] == "default" and name:
                v = w[1]
                if kind == "bool" and v == "n":
                    continue
                print("-DCONFIG_%s=%s" % (name, v))


def main(argv):
    if len(argv) != 3:
        sys.exit(__doc__)
    {"platformio": platformio, "arduino": arduino,
     "kconfig": kconfig}[argv[1]](argv[2])


if __name__ == "__main__":
    main(sys.argv)
