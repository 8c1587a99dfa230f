"""Where a public stroke set lies and how it is read (`Entry`): one pinned entry a repository folder, shared by
`public_sets` (which gathers them) and the readers of each search's forms (`fourth_sets`, `fifth_sets`)."""

from __future__ import annotations

from typing import NamedTuple

ONE, PER_FOLDER = "one", "per-folder"
XML, ACCORD, JAVA, INKML, QUICKDRAW, SMARTINK = "xml", "accord", "java", "inkml", "quickdraw", "smartink"
GESTER = "gester"


class Entry(NamedTuple):
    set_name: str
    repo: str
    commit: str
    folder: str
    device: str | None
    """None: the file says (MMG's InputType)."""
    layout: str
    """`ONE` (the folder is one person, named by `person`) or `PER_FOLDER` (each subfolder is one person)."""
    person: str = ""
    only: tuple[str, ...] = ()
    """`PER_FOLDER`: the subfolders read (all when empty)."""
    form: str = XML
    """`XML`: a gesture a file ($1 or $N form); `ACCORD`: a file a label of ``<Sequence>`` samples (the Accord.NET
    gesture sample's form); `JAVA`: a folder a label of Java-serialised samples; `INKML`: a diagram a file, its
    symbols trace groups labelled by their ``truth`` annotation, its writer named in the file (the FC database);
    `QUICKDRAW`: Quick, Draw! raw NDJSON, a file a category (``only``: the categories read), a drawing's person its
    country; `SMARTINK`: TutorBoard's gzipped corpora (``only``: the files read), their person ``person``
    (`fourth_sets`); `GESTER`: the unified JSON of the Gester evaluation tool, a gesture a file in the folders
    ``only`` names (searched to any depth), its person ``person`` formatted with the file's folders below ``folder``
    (``{0}`` the first), its device ``device`` with ``{os}`` the file's device description (`fifth_sets`)."""
    rename: tuple[str, str] = ("", "")
    """`PER_FOLDER`: (a prefix put before, a suffix taken off) each subfolder's name to name its person, so that one
    person's folders on several devices are one source (``user01mouse`` -> ``user01``) and two studies of one team
    are not (``user1`` -> ``trackpad-user1``)."""
