"""Every public class, function, method and property of the camcov module says what it is:
help(camcov.World) teaches. The walker is checked on objects made to lack docstrings, so that a
docstring removed from the module would be found."""
import inspect
import re
import types

import camcov

# pybind11 writes each function's signature as the first lines of its __doc__ ("name(args) ->
# type", or "Overloaded function." and numbered signatures): those say nothing a person wrote.
SIGNATURE = re.compile(r"^\s*(\d+\. )?[A-Za-z_][\w.]*\(.*\)( -> .*)?$|^\s*Overloaded function\.$")


def written(doc):
    """The text of a docstring beyond pybind11's signature lines."""
    lines = [line for line in (doc or "").splitlines() if line.strip()]
    return " ".join(line for line in lines if not SIGNATURE.match(line)).strip()


def public(names):
    return [n for n in names if not n.startswith("_") or n == "__init__"]


def undocumented(module):
    """'module.name' of every public class, function, method and property without a docstring."""
    missing = []
    for name in public(sorted(vars(module))):
        value = vars(module)[name]
        where = f"{module.__name__}.{name}"
        if inspect.isclass(value):
            if not written(value.__doc__):
                missing.append(where)
            for member in public(sorted(vars(value))):
                attr = vars(value)[member]
                if isinstance(attr, property) or inspect.isroutine(attr) or \
                        type(attr).__name__ == "instancemethod":
                    if not written(attr.__doc__):
                        missing.append(f"{where}.{member}")
        elif inspect.isroutine(value) and not written(value.__doc__):
            missing.append(where)
    return missing


def test_every_public_name_of_the_module_has_a_docstring():
    assert undocumented(camcov) == []
    assert written(camcov.__doc__)


def test_a_missing_docstring_is_found():
    fake = types.ModuleType("fake")

    class Documented:
        """Says what it is."""

        def method(self):
            """Says what it does."""

        @property
        def value(self):
            """Says what it holds."""

    class Bare:
        def method(self):
            pass

        @property
        def value(self):
            return 1

    def bare_function():
        pass

    fake.Documented, fake.Bare, fake.bare_function = Documented, Bare, bare_function
    assert undocumented(fake) == ["fake.Bare", "fake.Bare.method", "fake.Bare.value",
                                  "fake.bare_function"]
    # A pybind11 function whose docstring is only its signature counts as bare too.
    assert written("load_scene(file: str) -> camcov.Scene\n") == ""
    assert written("load_scene(file: str) -> camcov.Scene\n\nLoads a scene.\n") == \
        "Loads a scene."


def test_the_module_s_own_docstrings_are_what_the_walker_reads():
    # The walker sees a docstring of the real module: taking one away is noticed.
    assert "camcov.World.targets" not in undocumented(camcov)
    doc = camcov.World.targets.__doc__
    assert "(n, 2)" in doc
    assert "camcov.Scene.world_at" not in undocumented(camcov)
