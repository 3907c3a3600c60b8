"""Jinja2 configured like SMACHA's templater: lstrip_blocks, no trim_blocks, jinja2.ext.do, the
custom tests `expression` and `not_string` and filter `exptostr`, and the skip-block token
filter behind SMACHA's block rendering. Used by run_diff.py (the reference of the differential
tests) and by bench/tmpl_bench_jinja.py. Written for smachac from SMACHA's documented behaviour.
"""
import numbers
import re

import jinja2
import jinja2.meta
from jinja2.ext import Extension


class SkipBlocks(Extension):
    """Removes every `{% block NAME %}...{% endblock %}` whose NAME is in
    environment.skip_blocks from the token stream, nested blocks included."""

    def __init__(self, environment):
        super().__init__(environment)
        environment.extend(skip_blocks=[])

    def filter_stream(self, stream):
        depth = 0
        skipping_at = 0
        closing = False
        for token in stream:
            if token.type == "block_begin" and stream.current.test("name:block"):
                depth += 1
                if stream.look().value in self.environment.skip_blocks and not skipping_at:
                    skipping_at = depth
            if token.type == "name" and token.value == "endblock":
                closing = True
            if not skipping_at:
                yield token
            if token.type == "block_end" and closing:
                closing = False
                if skipping_at == depth:
                    skipping_at = 0
                depth -= 1


def exptostr(value):
    return re.sub(r"`(.*)`", r"\1", value)


def expression(value):
    return re.match(r"`.*`$", value) is not None


def not_string(value):
    if isinstance(value, (list, dict)) or isinstance(value, numbers.Number):
        return True
    if isinstance(value, str):
        try:
            float(value)
            return True
        except ValueError:
            pass
        if re.fullmatch(r"(\w+[.])+\w+", value) or re.match(r".+\(.*\)$", value):
            return True
    return False


def make_env(loader, skip=()):
    env = jinja2.Environment(loader=loader, extensions=["jinja2.ext.do", SkipBlocks],
                             trim_blocks=False, lstrip_blocks=True)
    env.skip_blocks.extend(skip)
    env.tests["expression"] = expression
    env.tests["not_string"] = not_string
    env.filters["exptostr"] = exptostr
    return env


def all_blocks(env, name, seen=None):
    """The block names of `name` and of every template it references, recursively."""
    seen = set() if seen is None else seen
    if name in seen:
        return set()
    seen.add(name)
    source = env.loader.get_source(env, name)[0]
    names = set(env.get_template(name).blocks)
    for ref in jinja2.meta.find_referenced_templates(env.parse(source)):
        if ref is not None:
            names |= all_blocks(env, ref, seen)
    return names


def block_skip_list(blocks, block, extra=()):
    """What SMACHA's render_block skips: every other block, and meta unless asked for."""
    skipped = [b for b in blocks if b != block] + list(extra)
    return skipped if block == "meta" or "meta" in skipped else skipped + ["meta"]


def strip_block(text):
    text = text.strip()
    return text + "\n" if text else text
