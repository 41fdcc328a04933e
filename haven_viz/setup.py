from setuptools import find_packages, setup

package_name = "haven_viz"

setup(
    name=package_name,
    version="0.1.0",
    packages=find_packages(exclude=["test"]),
    package_data={package_name: ["py.typed"]},
    data_files=[
        ("share/ament_index/resource_index/packages", [f"resource/{package_name}"]),
        (f"share/{package_name}", ["package.xml"]),
    ],
    install_requires=["setuptools", "haven_sim"],
    zip_safe=True,
    maintainer="HAVEN maintainers",
    maintainer_email="haven@example.org",
    description="HAVEN AR cue markers and viewer configs",
    license="Apache-2.0",
    entry_points={"console_scripts": []},
)
