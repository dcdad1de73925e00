"""A block of a Markdown page that a script writes from kept results:
the lines between two marker comments, replaced whole, or compared (a
test's -check) without writing."""


class ReadmeBlockError(ValueError):
    """A page without the markers, or whose block is not the one given."""


def write(path, begin, end, lines, check=False, command="the report"):
    """Replace the lines between the markers begin and end of the page at
    path by lines (the markers kept); with check, write nothing and raise
    ReadmeBlockError when the page's block differs, naming command as the
    one that writes it."""
    with open(path) as f:
        text = f.read()
    if begin not in text or end not in text:
        raise ReadmeBlockError("%s: no markers %s ... %s" % (path, begin, end))
    head, rest = text.split(begin, 1)
    tail = rest.split(end, 1)[1]
    new = head + begin + "\n" + "\n".join(lines) + "\n" + end + tail
    if check:
        if new != text:
            raise ReadmeBlockError("%s: the block %s is not the kept results' (run %s)"
                                   % (path, begin, command))
        return
    with open(path, "w") as f:
        f.write(new)
