#!/usr/bin/env python3
"""The include check of CI: runs include-what-you-use (Debian's `iwyu`) over our C++ files and fails
when it finds an #include that a file of ours does not use, printing FILE:LINE and the include.

    scripts/check_includes.py [-p BUILD_DIR] [-j JOBS] [--fix] [--verbose] [FILE ...]

BUILD_DIR (default: build) holds the compile_commands.json that the configure writes, and the
generated headers the sources include, so build it first (scripts/setup.sh). With no FILE, every
.cpp of app/, engine/, cli/, bench/ and tests/ in that database is checked, and with it each header
of ours that has no .cpp of its own, as the .cpp files that include it see it. A FILE may be a .cpp,
a header (checked through its .cpp, or through the .cpp files that include it) or a folder.

Only unused includes fail the check. iwyu's other advice, the includes a file should add, is
shown by --verbose, with iwyu's reasons; --fix deletes the unused include lines it reports.
The mappings in scripts/iwyu.imp tell iwyu which public header of a library provides a symbol
that the library defines in an internal one.
"""

import argparse
import concurrent.futures
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUR_FOLDERS = ("app", "engine", "cli", "bench", "tests")
MAPPING = os.path.join(ROOT, "scripts", "iwyu.imp")

# Includes that are used although clang cannot see it, so iwyu's advice to remove them is wrong.
KEEP = {
    # Declares libm's functions as `simd` for GCC only (the header explains why); iwyu parses with
    # clang, where the declarations are compiled out, so the include looks unused.
    '"core/vector_math.h"': "its declarations are GCC-only",
    '"vector_math.h"': "its declarations are GCC-only",
    # syscall(2) documents <sys/syscall.h> for the SYS_ numbers; iwyu 0.18's glibc table calls it
    # private and asks for <syscall.h>, which only includes it.
    "<sys/syscall.h>": "iwyu wants <syscall.h> instead",
}

SHOULD_ADD = re.compile(r"^(.*) should add these lines:$")
SHOULD_REMOVE = re.compile(r"^(.*) should remove these lines:$")
FULL_LIST = re.compile(r"^The full include-list for (.*):$")
CORRECT = re.compile(r"^\((.*) has correct #includes/fwd-decls\)$")
REMOVE_LINE = re.compile(r"^- (#include\s*[<\"][^>\"]+[>\"]).*// lines (\d+)-(\d+)$")
ERROR = re.compile(r"^(.*?):(\d+):(\d+): (?:fatal )?error: (.*)$")


def ours(path):
    relative = os.path.relpath(path, ROOT)
    return not relative.startswith("..") and relative.split(os.sep)[0] in OUR_FOLDERS


def relative(path):
    return os.path.relpath(path, ROOT)


def load_database(build):
    path = os.path.join(build, "compile_commands.json")
    if not os.path.exists(path):
        sys.exit(
            f"check_includes: {path} is missing; configure and build {build} first "
            "(scripts/setup.sh writes it)"
        )
    with open(path) as file:
        entries = json.load(file)
    # A file built into several targets (tests/test_support.cpp) is checked once.
    database = {}
    for entry in entries:
        file = os.path.realpath(os.path.join(entry["directory"], entry["file"]))
        database.setdefault(file, entry)
    return database


def header_only_headers():
    """Our headers without a .cpp beside them: iwyu checks those only where asked to."""
    headers = []
    for folder in OUR_FOLDERS:
        for directory, _, names in os.walk(os.path.join(ROOT, folder)):
            for name in names:
                if name.endswith(".h") and not os.path.exists(os.path.join(directory, name[:-2] + ".cpp")):
                    headers.append(os.path.realpath(os.path.join(directory, name)))
    return sorted(headers)


def includers(database, header):
    """The .cpp files in the database that include `header` by its file name."""
    name = os.path.basename(header)
    found = []
    for file in database:
        if not ours(file):
            continue
        with open(file, errors="replace") as source:
            if re.search(r'#include\s*"(?:[^"]*/)?' + re.escape(name) + '"', source.read()):
                found.append(file)
    return found


def select(database, requested):
    """The .cpp files to run iwyu on, and the header-only headers to report on."""
    headers = header_only_headers()
    if not requested:
        return sorted(file for file in database if ours(file)), headers
    files, wanted_headers = set(), []
    for path in requested:
        path = os.path.realpath(path)
        if os.path.isdir(path):
            files.update(file for file in database if file.startswith(path + os.sep) and ours(file))
            wanted_headers += [header for header in headers if header.startswith(path + os.sep)]
        elif path.endswith(".cpp"):
            if path not in database:
                sys.exit(f"check_includes: {relative(path)} is not in the compile database")
            files.add(path)
        elif path.endswith(".h"):
            source = path[:-2] + ".cpp"
            if source in database:
                files.add(source)  # iwyu checks a .cpp's own header with it
            else:
                users = includers(database, path)
                if not users:
                    sys.exit(f"check_includes: no .cpp in the compile database includes {relative(path)}")
                files.update(users)
                wanted_headers.append(path)
        else:
            sys.exit(f"check_includes: {path}: give a .cpp, a .h or a folder")
    return sorted(files), wanted_headers


def iwyu_command(entry, headers):
    arguments = entry.get("arguments") or shlex.split(entry["command"])
    command = ["include-what-you-use"]
    command += ["-Xiwyu", f"--mapping_file={MAPPING}"]
    # A header is never swapped for a forward declaration: we include what we name.
    command += ["-Xiwyu", "--no_fwd_decls"]
    command += ["-Xiwyu", "--max_line_length=200"]
    for header in headers:
        command += ["-Xiwyu", f"--check_also={header}"]
    # The flags are GCC's; clang does not know some of them, and its warnings are not this check's.
    command += arguments[1:] + ["-w", "-Wno-error"]
    return command


def run_iwyu(entry, headers):
    process = subprocess.run(
        iwyu_command(entry, headers),
        cwd=entry["directory"],
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
    )
    return process.stdout


def parse(output):
    """(unused includes as {(file, line): include}, files iwyu reported on, compile errors)."""
    unused, reported, errors = {}, set(), []
    state, current = None, None
    for line in output.splitlines():
        if match := ERROR.match(line):
            errors.append(line)
            continue
        if match := SHOULD_ADD.match(line):
            state, current = "add", os.path.realpath(match.group(1))
            reported.add(current)
        elif match := SHOULD_REMOVE.match(line):
            state, current = "remove", os.path.realpath(match.group(1))
        elif FULL_LIST.match(line) or line == "---" or not line.strip():
            state = None
        elif match := CORRECT.match(line):
            reported.add(os.path.realpath(match.group(1)))
        elif state == "remove" and (match := REMOVE_LINE.match(line)):
            unused[(current, int(match.group(2)))] = match.group(1)
    return unused, reported, errors


def fix(unused):
    """Deletes the reported include lines, and a blank line left doubled by a deletion."""
    by_file = {}
    for (file, line), include in unused.items():
        by_file.setdefault(file, []).append(line)
    for file, lines in by_file.items():
        with open(file) as source:
            text = source.read().split("\n")
        for line in sorted(lines, reverse=True):
            if not text[line - 1].startswith("#include"):
                sys.exit(f"check_includes: {relative(file)}:{line} is not an #include; not fixing")
            del text[line - 1]
            if 1 < line <= len(text) and not text[line - 2].strip() and not text[line - 1].strip():
                del text[line - 1]
        with open(file, "w") as source:
            source.write("\n".join(text))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("-p", dest="build", default=os.path.join(ROOT, "build"), help="build folder")
    parser.add_argument("-j", dest="jobs", type=int, default=2, help="iwyu processes at once")
    parser.add_argument("--fix", action="store_true", help="delete the unused include lines found")
    parser.add_argument("--verbose", action="store_true", help="print all of iwyu's advice")
    parser.add_argument("files", nargs="*")
    options = parser.parse_args()

    if shutil.which("include-what-you-use") is None:
        sys.exit(
            "check_includes: include-what-you-use is not installed; install Debian's iwyu package "
            "(it is in scripts/packages.txt, which scripts/setup.sh installs)"
        )
    start = time.monotonic()
    database = load_database(os.path.realpath(options.build))
    files, headers = select(database, options.files)

    unused, reported, failed = {}, set(), []
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, options.jobs)) as pool:
        outputs = pool.map(lambda file: (file, run_iwyu(database[file], headers)), files)
        for file, output in outputs:
            if options.verbose:
                print(output)
            file_unused, file_reported, errors = parse(output)
            unused.update(file_unused)
            reported |= file_reported
            if errors or file not in file_reported:
                # A file clang cannot compile is a file nobody checked: that fails the check too.
                failed.append(file)
                reasons = errors[:10] or output.strip().splitlines()[-5:]
                print(f"{relative(file)}: iwyu could not analyse it:", *reasons, sep="\n  ")

    findings = {
        key: include for key, include in unused.items() if ours(key[0]) and include.split(None, 1)[1] not in KEEP
    }
    for (file, line), include in sorted(findings.items()):
        print(f"{relative(file)}:{line}: unused {include}")
    print(
        f"check_includes: {len(files)} files and {len(headers)} header-only headers checked "
        f"in {time.monotonic() - start:.0f} s: {len(findings)} unused includes "
        f"in {len({file for file, _ in findings})} files"
    )
    if options.fix and findings:
        fix(findings)
        print("check_includes: removed them; build, and run the check again")
    if failed:
        return 2
    return 1 if findings and not options.fix else 0


if __name__ == "__main__":
    sys.exit(main())
