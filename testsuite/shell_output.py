"""
MODULE:    testsuite/shell_output.py (r3.sbrt addon)
PURPOSE:   Reads the -g output of the r3.sbrt modules as a shell does
           (issue 48, item 1): each line is key=WORD, where WORD is plain
           or single-quoted; a record (channel=, variable=) is one word of
           key=value fields joined by '|'
COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
"""
import shlex


def shell_pairs(output):
    """(key, value) of every key=WORD line of `output`, the words unquoted."""
    pairs = []
    for line in output.splitlines():
        if "=" not in line:
            continue
        key, word = line.split("=", 1)
        words = shlex.split(word) if word else [""]
        assert len(words) == 1, f"not one shell word: {line!r}"
        pairs.append((key, words[0]))
    return pairs


def shell_values(output):
    """key -> value of every line of `output` (the last one of a key)."""
    return dict(shell_pairs(output))


def shell_records(output, key):
    """The fields of every `key=` record line: a list of dicts, each with
    `key` for the record's first field."""
    records = []
    for k, value in shell_pairs(output):
        if k != key:
            continue
        first, *rest = value.split("|")
        fields = {key: first}
        fields.update(f.split("=", 1) for f in rest)
        records.append(fields)
    return records
