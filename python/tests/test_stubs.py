"""The type stubs (.pyi) installed beside the module say what the package
has: every public name, every function's parameters in their order."""

import ast
import inspect
import os

import contactlaws
from contactlaws import _contactlaws, commands

PACKAGE = os.path.dirname(contactlaws.__file__)


def stub(name):
    with open(os.path.join(PACKAGE, name)) as f:
        return ast.parse(f.read())


def defined(tree):
    """name -> the FunctionDef or ClassDef of the stub's top level."""
    return {node.name: node for node in tree.body
            if isinstance(node, (ast.FunctionDef, ast.ClassDef))}


def parameters(function):
    a = function.args
    return [p.arg for p in a.posonlyargs + a.args + a.kwonlyargs]


def test_the_stubs_are_installed_with_the_module():
    for name in ("__init__.pyi", "commands.pyi", "_contactlaws.pyi", "py.typed"):
        assert os.path.exists(os.path.join(PACKAGE, name)), name


def test_every_public_name_is_in_the_stubs():
    tree = stub("__init__.pyi")
    names = set(defined(tree))
    for node in tree.body:
        if isinstance(node, ast.ImportFrom):
            names.update(alias.asname or alias.name for alias in node.names)
    assert set(contactlaws.__all__) <= names


def test_the_stubs_give_each_function_its_parameters():
    for module, name in ((contactlaws, "__init__.pyi"), (commands, "commands.pyi")):
        for stub_name, node in defined(stub(name)).items():
            if isinstance(node, ast.FunctionDef):
                real = inspect.signature(getattr(module, stub_name))
                assert parameters(node) == list(real.parameters), stub_name


def test_the_simulation_stub_has_the_modules_members():
    members = set()
    for name in ("__init__.pyi", "_contactlaws.pyi"):
        for node in defined(stub(name)).values():
            if isinstance(node, ast.ClassDef) and node.name in ("Simulation", "_Simulation"):
                members.update(n.name for n in node.body if isinstance(n, ast.FunctionDef))
    public = {m for m in dir(contactlaws.Simulation) if not m.startswith("_")}
    assert public <= members, public - members
    # the stub of the extension module names what it exports
    assert isinstance(_contactlaws.Error, type)


def test_help_gives_units():
    for function, units in ((contactlaws.run, ["s", "m/s"]), (contactlaws.compare, ["s/m"]),
                            (contactlaws.restitution, ["m/s", "N"])):
        doc = inspect.getdoc(function)
        for unit in units:
            assert f"{unit})" in doc or f"{unit}," in doc or f" {unit} " in doc, (function, unit)
    assert "m/s" in inspect.getdoc(contactlaws.Simulation.qvel)
