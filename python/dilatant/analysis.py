"""The analysis entry points under the names of the specification
(`dilatant.analysis.fit_wyart_cates`); the same functions as dilatant.analyze,
dilatant.fit_wyart_cates and dilatant.predict (rheology.py)."""
from .rheology import (AnalysisResult, WyartCatesResult, analyze, fit_wyart_cates,  # noqa: F401
                       predict)

__all__ = ["AnalysisResult", "WyartCatesResult", "analyze", "fit_wyart_cates", "predict"]
