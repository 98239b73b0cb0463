"""Records from delimited text files (CSV): the columns a model is identified on, checked.

A file has one sample per row. Its first row may name the columns (then a column is given by its
name, or by its 0-based position); every other field must be a finite number.
"""

from __future__ import annotations

import csv
import math
import os
from typing import List, Sequence, Tuple, Union

import numpy as np

__all__ = ["read_columns", "write_columns"]

Column = Union[str, int]


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def read_columns(path: Union[str, os.PathLike], columns: Sequence[Column], delimiter: str = ",") -> List[np.ndarray]:
    """The given columns of a delimited text file as float arrays, in the order asked for.

    Parameters
    ----------
    path : str or path-like
        The file: one sample per row, the first row optionally the columns' names.
    columns : sequence of str or int
        Each column by its name in the first row, or by its 0-based position (an int, or a string of
        digits where the file has no such name).
    delimiter : str, default ","
        What separates the fields of a row.

    Returns
    -------
    list of numpy.ndarray
        One 1-D float array per column asked for, all of the file's length.

    Raises
    ------
    ValueError
        The file does not exist or cannot be read, a column is not in it, a row has too few fields, or a
        field is not a finite number; the message names the file, the row (1-based, as an editor shows
        it) and the column.
    """
    name = os.fspath(path)
    if not os.path.isfile(name):
        raise ValueError(f"bonl: {name}: no such file")
    try:
        with open(name, newline="") as handle:
            rows = [row for row in csv.reader(handle, delimiter=delimiter) if any(field.strip() for field in row)]
    except (OSError, UnicodeDecodeError, csv.Error) as error:
        raise ValueError(f"bonl: {name}: cannot be read as delimited text ({error})") from None
    if not rows:
        raise ValueError(f"bonl: {name}: the file holds no rows")
    header = [field.strip() for field in rows[0]]
    has_header = not all(_is_number(field) for field in header)
    names = header if has_header else [str(i) for i in range(len(header))]
    first_data_row = 2 if has_header else 1
    data = rows[1:] if has_header else rows
    if not data:
        raise ValueError(f"bonl: {name}: the file holds no samples, only its header")

    indices = []
    for column in columns:
        if isinstance(column, str) and column in names:
            indices.append(names.index(column))
        elif isinstance(column, (int, np.integer)) or (isinstance(column, str) and column.isdigit()):
            index = int(column)
            if not 0 <= index < len(names):
                raise ValueError(f"bonl: {name}: no column {index}: the file has {len(names)} (0 to {len(names) - 1})")
            indices.append(index)
        else:
            raise ValueError(f"bonl: {name}: no column {column!r}; its columns are "
                             + ", ".join(repr(n) for n in names))

    out = [np.empty(len(data)) for _ in indices]
    for i, row in enumerate(data):
        for j, index in enumerate(indices):
            where = f"row {i + first_data_row}, column {names[index]!r}"
            if index >= len(row):
                raise ValueError(f"bonl: {name}: {where}: the row has only {len(row)} fields")
            field = row[index].strip()
            try:
                value = float(field)
            except ValueError:
                raise ValueError(f"bonl: {name}: {where}: {field!r} is not a number") from None
            if not math.isfinite(value):
                raise ValueError(f"bonl: {name}: {where}: {field!r} is not a finite number")
            out[j][i] = value
    return out


def write_columns(path: Union[str, os.PathLike], columns: Sequence[Tuple[str, np.ndarray]]) -> None:
    """Writes named columns of equal length as a CSV file with a header row.

    Parameters
    ----------
    path : str or path-like
        Where; an existing file is replaced.
    columns : sequence of (str, array_like)
        Each column's name and values.

    Raises
    ------
    ValueError
        The columns have different lengths or none is given.
    """
    if not columns:
        raise ValueError("bonl: write_columns: no columns given")
    values = [np.asarray(v, dtype=float).ravel() for _, v in columns]
    if len({v.size for v in values}) != 1:
        raise ValueError("bonl: write_columns: the columns have different lengths "
                         + ", ".join(f"{n} {v.size}" for (n, _), v in zip(columns, values)))
    with open(os.fspath(path), "w", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow([n for n, _ in columns])
        for row in zip(*values):
            writer.writerow([repr(float(x)) for x in row])
