"""The reader of `granulab analyze` tables (docs/analysis.md "Table format") shared by the
studies' summary scripts (piles/, perturb/, crater/ summarize.py). Standard library only.
"""
import os


def table(path):
    """(notes, rows) of an analysis CSV: the `# key = value unit` notes as numbers (other `# `
    lines are remarks) and the rows as dicts by quantity name (units cut from the header).
    A table the analysis did not write gives ({}, [])."""
    notes, rows, header = {}, [], None
    if not os.path.exists(path):
        return notes, rows
    with open(path) as f:
        for line in f:
            if line.startswith('# '):
                body = line[2:].strip()
                if '=' in body:
                    k, v = body.split('=', 1)
                    try:
                        notes[k.strip()] = float(v.split()[0])
                    except (ValueError, IndexError):
                        pass
                continue
            if not line.strip():
                continue
            cells = line.strip().split(',')
            if header is None:
                header = [c.split(' [')[0] for c in cells]
            else:
                rows.append(dict(zip(header, (float(c) for c in cells))))
    return notes, rows
