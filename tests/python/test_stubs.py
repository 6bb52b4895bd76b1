"""The type stubs (lensrt/__init__.pyi) against the module: every class,
method, property and keyword an IDE completes exists, and every public name
of the module has a stub."""

import ast
import inspect
import pathlib

import lensrt

STUB = ast.parse((pathlib.Path(lensrt.__file__).parent / "__init__.pyi").read_text())


def stub_classes():
    return {n.name: n for n in STUB.body if isinstance(n, ast.ClassDef)}


def test_every_stub_member_exists():
    for name, cls in stub_classes().items():
        assert hasattr(lensrt, name), name
        for member in cls.body:
            if isinstance(member, ast.FunctionDef) and member.name != "__init__":
                assert hasattr(getattr(lensrt, name), member.name), f"{name}.{member.name}"


def test_every_public_name_has_a_stub():
    stubbed = set(stub_classes()) | {n.name for n in STUB.body if isinstance(n, ast.FunctionDef)}
    stubbed |= {t.id for n in STUB.body if isinstance(n, ast.AnnAssign) for t in [n.target]}
    for name in lensrt.__all__:
        assert name in stubbed, name
    for name in ("Lens", "Scene", "RenderResult"):
        public = {m for m in dir(getattr(lensrt, name)) if not m.startswith("_")}
        members = {m.name for m in stub_classes()[name].body if isinstance(m, ast.FunctionDef)}
        assert public <= members, f"{name}: no stub for {public - members}"


def test_stub_keywords_are_the_bindings_keywords():
    # pybind11 names each argument in the docstring's signature line.
    for cls_name, method in (("Lens", "info"), ("Lens", "trace"), ("Lens", "spot"),
                             ("Lens", "relative_illumination"), ("Lens", "distortion"), ("Lens", "focus"),
                             ("Lens", "psf"), ("Lens", "mtf")):
        stub = next(m for m in stub_classes()[cls_name].body if isinstance(m, ast.FunctionDef) and m.name == method)
        keywords = [a.arg for a in stub.args.args[1:]]
        signature = getattr(getattr(lensrt, cls_name), method).__doc__.splitlines()[0]
        for k in keywords:
            assert f"{k}:" in signature, f"{cls_name}.{method}: {k} not in {signature}"
    diff_stub = next(n for n in STUB.body if isinstance(n, ast.FunctionDef) and n.name == "diff")
    signature = lensrt.diff.__doc__.splitlines()[0]
    for k in [a.arg for a in diff_stub.args.args + diff_stub.args.kwonlyargs]:
        assert f"{k}:" in signature, k
    assert inspect.isclass(lensrt.TraceResult) and lensrt.TraceResult._fields == (
        "points", "directions", "weights", "passed")
