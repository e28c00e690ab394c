# This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
# The type stubs (python/cv_essential.pyi) name exactly the module's public functions and classes,
# and each class's attributes.
import ast
import pathlib

import cv_essential

STUB = pathlib.Path(__file__).resolve().parents[1] / "cv_essential.pyi"


def stub_tree():
    return ast.parse(STUB.read_text())


def test_stub_names_are_the_module_names():
    tree = stub_tree()
    stub = {n.name for n in tree.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    # Module-level annotations are the constants (ArrayLike is an alias of the stubs only).
    stub |= {n.target.id for n in tree.body if isinstance(n, ast.AnnAssign)}
    # Aliases (recoverPoseIter = recoverPose) name the same function.
    stub |= {t.id for n in tree.body if isinstance(n, ast.Assign) for t in n.targets
             if isinstance(t, ast.Name) and t.id != "ArrayLike" and t.id != "Array"}
    module = {n for n in dir(cv_essential) if not n.startswith("_")}
    assert stub == module


def test_stub_classes_list_the_attributes():
    for node in stub_tree().body:
        if not isinstance(node, ast.ClassDef):
            continue
        declared = {a.target.id for a in node.body if isinstance(a, ast.AnnAssign)}
        actual = {n for n in dir(getattr(cv_essential, node.name)) if not n.startswith("_")}
        assert declared == actual, node.name
