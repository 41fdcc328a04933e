from setuptools import find_packages, setup

package_name = "haven_scenarios"

setup(
    name=package_name,
    version="0.1.0",
    packages=find_packages(exclude=["test"]),
    package_data={package_name: ["py.typed"]},
    data_files=[
        ("share/ament_index/resource_index/packages", [f"resource/{package_name}"]),
        (f"share/{package_name}", ["package.xml"]),
    ],
    install_requires=["setuptools", "haven_sim", "haven_viz"],
    zip_safe=True,
    maintainer="HAVEN maintainers",
    maintainer_email="haven@example.org",
    description="HAVEN study scenarios, sessions and the haven command",
    license="Apache-2.0",
    entry_points={
        "console_scripts": [
            "haven = haven_scenarios.cli:main",
            "demo_driver = haven_scenarios.nodes.demo_driver:main",
            "goal_client = haven_scenarios.nodes.goal_client:main",
        ],
    },
)
