"""The type stubs (dilatant/_core.pyi) against the compiled module: every name
and parameter the stubs declare is the module's, and every public one of the
module is declared, so that an editor never shows a signature that is wrong."""
import ast
import re
from pathlib import Path

import dilatant
from dilatant import _core

STUB = Path(dilatant.__file__).with_name("_core.pyi")


def stub_declarations():
    """{function: [parameters]} and {class: {member: [parameters] or None}}."""
    tree = ast.parse(STUB.read_text())
    functions, classes = {}, {}

    def parameters(node):
        return [a.arg for a in node.args.args if a.arg != "self"]

    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            functions[node.name] = parameters(node)
        elif isinstance(node, ast.ClassDef):
            classes[node.name] = {n.name: parameters(n) for n in node.body
                                  if isinstance(n, ast.FunctionDef)}
    return functions, classes


def runtime_parameters(function):
    """The parameter names of pybind11's signature line, e.g. 'f(a: int, b: str) -> None'."""
    line = (function.__doc__ or "").splitlines()[0]
    inside = line[line.index("(") + 1:line.rindex(")")]
    names = [re.match(r"\s*(\w+)", part).group(1) for part in re.split(r",(?![^\[]*\])", inside)
             if part.strip()]
    return [n for n in names if n != "self"]


def public(names):
    return {n for n in names if not n.startswith("_")}


def test_every_function_of_the_module_is_declared_with_its_parameters():
    functions, classes = stub_declarations()
    module_functions = {n for n in public(dir(_core))
                        if callable(getattr(_core, n)) and not isinstance(getattr(_core, n), type)}
    assert module_functions == set(functions)
    for name, declared in functions.items():
        assert runtime_parameters(getattr(_core, name)) == declared, name


def test_every_class_and_member_is_declared():
    _, classes = stub_declarations()
    module_classes = {n for n in public(dir(_core)) if isinstance(getattr(_core, n), type)}
    assert module_classes == set(classes)
    for name, members in classes.items():
        cls = getattr(_core, name)
        if issubclass(cls, Exception):
            continue
        assert public(vars(cls)) == public(members), name
        for member, declared in members.items():
            value = vars(cls).get(member)
            if isinstance(value, property) or member.startswith("__"):
                continue
            function = getattr(cls, member)
            if member == "__init__" or not callable(function):
                continue
            assert runtime_parameters(function) == declared, f"{name}.{member}"
